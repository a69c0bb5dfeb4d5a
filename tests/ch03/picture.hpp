// The small picture that chapter 03's picture test renders, shared with make_references so that
// the reference and the test render exactly the same thing.
#pragma once

#include "03_reflection_refraction/figure.hpp"

namespace rt::pictures {

inline Image ch03() { return ch03::render_figure(quiet_render(96, 54, 1)); }

}  // namespace rt::pictures
