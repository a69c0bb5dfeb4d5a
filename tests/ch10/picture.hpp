// The small picture that chapter 10's picture test renders, shared with make_references: the
// teapot in a stadium through your BVH (the render alone).
#pragma once

#include "10_hierarchies/figure.hpp"

namespace rt::pictures {

inline Image ch10() { return ch10::render_through_bvh(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
