// Chapter 06's scene: chapter 04's lit scene as it is, since depth of field changes the camera and
// not the scene, plus the one thing the figure needs to show blur on a flat floor: a checkerboard.
// A plain floor has no edges to blur; its squares shrink with depth, so the floor shows the focus
// falling off behind and in front of the plane of sharp focus (the kit models only what a scene
// requires, and the figure requires this).
#pragma once

#include "04_shadow_feelers/scene.hpp"

#include <cmath>

namespace rt {

// Squares `size` wide on the plane y = const, every other one `dark` times as bright. It applies
// to the objects of one material, which must be diffuse only (no highlight): chapter 04's shade
// is then k_d times the light arriving, so scaling its result is scaling k_d, the square's colour.
struct Checkerboard {
    int material = -1;  // the material it paints; -1: none
    float size = 1.0f;
    float dark = 0.3f;
};

struct FocusScene {
    LitScene lit;
    Checkerboard checker;
};

// The factor the checkerboard puts on chapter 04's shade at the hit point p of `object`.
inline float checker_factor(const FocusScene& scene, int object, const point3& p)
{
    const Checkerboard& c = scene.checker;
    if (scene.lit.material_index(object) != c.material)
        return 1.0f;
    // Square (cx, cz) is dark when cx + cz is odd; fmod keeps this exact for far squares, where a
    // cast of the index to an integer would overflow (as chapter 01's floor does).
    const float cx = std::floor(p.x / c.size), cz = std::floor(p.z / c.size);
    return std::fmod(cx + cz, 2.0f) != 0.0f ? c.dark : 1.0f;
}

}  // namespace rt
