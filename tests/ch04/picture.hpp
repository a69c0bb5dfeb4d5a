// The small picture that chapter 04's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing.
#pragma once

#include "04_shadow_feelers/figure.hpp"

namespace rt::pictures {

inline Image ch04() { return ch04::render_figure(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
