// A scene file (NFF, common/nff.hpp) in chapter 06: chapter 04's scene (nff_scene.hpp there), no
// checkerboard, seen through a thin lens focused on the point the view looks at.
#pragma once

#include "04_shadow_feelers/nff_scene.hpp"
#include "06_depth_of_field/lens.hpp"
#include "06_depth_of_field/scene.hpp"

namespace rt {

// Why 1.5%: a little more than the figure's own ratio of aperture to focus distance (0.1 at about
// 7.6: 1.3%), which blurs what lies half as far or twice as far as the plane of focus by a few
// percent of the image height.
constexpr float nff_aperture_fraction = 0.015f;

inline FocusScene focus_scene(const NffScene& nff)
{
    return FocusScene{lit_scene(nff), Checkerboard{}};
}

// Focused on the view's `at`, which lies straight ahead: its depth is its distance from the eye.
inline ThinLens nff_lens(const NffScene& nff)
{
    const float focus = glm::length(nff.view.at - nff.view.from);
    return {nff_aperture_fraction * focus, focus};
}

}  // namespace rt
