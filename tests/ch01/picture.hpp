// The small picture that chapter 01's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing.
#pragma once

#include "01_ray_casting/figure.hpp"

namespace rt::pictures {

inline Image ch01() { return ch01::render_figure(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
