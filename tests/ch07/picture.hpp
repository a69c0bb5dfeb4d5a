// The small picture that chapter 07's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing: the figure's mountain through your
// grid (the render alone; the heat map beside it in the figure counts work, not colour).
#pragma once

#include "07_uniform_grid/figure.hpp"

namespace rt::pictures {

inline Image ch07() { return ch07::render_through_grid(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
