// The small picture that chapter 02's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing.
#pragma once

#include "02_spheres_triangles/figure.hpp"

namespace rt::pictures {

inline Image ch02() { return ch02::render_figure(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
