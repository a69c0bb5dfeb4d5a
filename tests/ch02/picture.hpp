// The small picture that chapter 02's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing.
#pragma once

#include "02_spheres_triangles/figure.hpp"

namespace rt::pictures {

inline Image ch02()
{
    RenderSettings s;
    s.width = 96;
    s.height = 54;
    s.spp = 1;
    s.show_progress = false;
    return ch02::render_figure(s);
}

}  // namespace rt::pictures
