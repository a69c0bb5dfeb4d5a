// SOLUTION BEGIN
// Chapter 06, depth of field: the reference solution.
//
// This file is also the source of exercises/06_depth_of_field.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 06, depth of field: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/06_depth_of_field/06_depth_of_field.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_06
// STUB // Stuck? Hints in tiers you open one at a time: chapters/06_depth_of_field/hints.md, or
// STUB // ./build/grade/hint 06.1 (tier 1, the idea), ./build/grade/hint 06.1 2 (the trap), ... 3 (the walk-through).
// STUB //
// STUB // This chapter builds on chapter 01 (primary_ray, the pinhole ray, which 06.3 calls); its
// STUB // program and figure also use chapter 02's spheres and triangles and chapter 04's shading.
#include "06_depth_of_field/06_depth_of_field.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
#include "01_ray_casting/01_ray_casting.hpp"

#include <cmath>

namespace rt {

// pi / 4: the angle each eighth of a square ring (half of one side) spans on its circle.
[[maybe_unused]] constexpr float quarter_pi = 0.785398163397448309616f;  // the stub of 06.1 leaves it unused

point2 concentric_disc(point2 square)
{
    // EXERCISE 06.1: Shirley and Chiu's concentric map, unit square -> unit disc
    // Return the point of the unit disc that square stands for: each square ring around the square's
    // centre goes onto the circle of its half-side, walked at an even pace. So the map preserves area,
    // puts the square's edges on the rim and its corners on the diagonals; the centre goes to (0, 0),
    // never a NaN. Lesson: "Sampling the lens: an area-preserving map (EXERCISE 06.1)".
    // Stuck? hint 06.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float a = 2.0f * square.x - 1.0f;
    const float b = 2.0f * square.y - 1.0f;
    if (a == 0.0f && b == 0.0f)
        return point2(0.0f);
    float r, phi;
    if (std::abs(a) >= std::abs(b)) {
        r = a;
        phi = quarter_pi * (b / a);
    } else {
        r = b;
        phi = 2.0f * quarter_pi - quarter_pi * (a / b);
    }
    return r * point2(std::cos(phi), std::sin(phi));
    // SOLUTION END
    // STUB return stub("06.1", point2(0.0f));
}

point3 focal_point(const Camera& cam, const ThinLens& lens, const Ray& pinhole)
{
    // EXERCISE 06.2: where the pinhole ray meets the plane of sharp focus
    // Return the point of pinhole (from the eye, unit direction, in front of the camera) on the plane
    // lens.focus_distance in front of the eye measured along -w, parallel to the window: a slanted ray
    // travels farther than that to reach it. Exact to float's own rounding, even with the eye 2e5
    // from the origin and a 179-degree view. Lesson: "The focal point: along -w, not along the ray
    // (EXERCISE 06.2)".
    // Stuck? hint 06.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float advance = glm::dot(pinhole.dir, -cam.w);
    return pinhole.at(lens.focus_distance / advance);
    // SOLUTION END
    // STUB return stub("06.2", pinhole.origin);
}

Ray thin_lens_ray(const Camera& cam, const ThinLens& lens, float x, float y, Rng& rng)
{
    // EXERCISE 06.3: the thin-lens ray through pixel position (x, y)
    // Return the ray, unit direction, from a uniform point of the lens (radius lens.aperture_radius
    // around the eye, in the camera's u, v plane) toward where the pixel's pinhole ray meets the plane
    // of focus; the lens point comes from rng's next two numbers, the first for x. An aperture of 0
    // (or -0) returns primary_ray's ray bit for bit and draws nothing; any other, however small, is a
    // lens. Lesson: "The thin-lens ray (EXERCISE 06.3)".
    // Stuck? hint 06.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const Ray pinhole = primary_ray(cam, x, y);
    if (lens.aperture_radius == 0.0f)
        return pinhole;
    point2 s;
    s.x = rng.next_float();
    s.y = rng.next_float();
    const point2 d = concentric_disc(s);
    const point3 on_lens = cam.eye + lens.aperture_radius * (d.x * cam.u + d.y * cam.v);
    return Ray{on_lens, glm::normalize(focal_point(cam, lens, pinhole) - on_lens)};
    // SOLUTION END
    // STUB return stub("06.3", Ray{cam.eye, -cam.w});
}

}  // namespace rt
