// The small picture that chapter 09's picture test renders, shared with make_references: the
// teapot in a stadium through your hashed grid (the render alone).
#pragma once

#include "09_hashed_voxels/figure.hpp"

namespace rt::pictures {

inline Image ch09() { return ch09::render_through_hashed(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
