// How a shadow feeler leaves its surface, and which query answers it: the knobs the chapter's
// program turns and its table measures. The rendering code passes them through untouched.
//
// A feeler starts on the surface it lights. Its origin, the hit point, is rounded to float, so it
// lies a little above or a little below the true surface, and a feeler that starts below re-finds
// its own surface at a tiny t: the dark speckles called shadow acne. Four answers: the first three
// fail at some scale, the last only on large surfaces lying in a coordinate plane, where the
// triangle test's own error bound takes over (README.md, "The measured problem" and "Where the
// robust offset stops, and the test's own bound"):
#pragma once

#include "common/interval.hpp"

namespace rt {

enum class Offset {
    none,    // the feeler starts at the hit point and accepts any t > 0: about half the feelers re-hit
    t_min,   // it accepts only t > t_min_default (common/interval.hpp, 1e-4): too small far from the
             // origin, where the hit point's rounding is larger; too large in a small scene
    normal,  // it starts at p + normal_offset n, n turned to the side it leaves: the same two failures
    robust,  // Wachter and Binder's scale-aware offset (EXERCISE 04.3): the kit's default
};

// Why 1e-4: the offset along the normal that pairs with t_min_default, the size a renderer of
// unit-sized scenes picks by trying. The program's table shows where it fails: above a scale of
// about 1e3 it is smaller than the hit point's rounding, below 1e-3 larger than the scene's gaps.
constexpr float normal_offset = 1e-4f;

// Which query answers "is anything between the point and the light?"
enum class ShadowQuery {
    any_hit,      // EXERCISE 04.2: stop at the first occluder found, whichever it is
    closest_hit,  // the nearest hit up to the light (chapter 01's QueryScene): the same answer, more work
    off,          // no feelers: every light is seen, no shadows at all (the trade's baseline)
};

struct FeelerSettings {
    Offset offset = Offset::robust;
    ShadowQuery query = ShadowQuery::any_hit;
};

}  // namespace rt
