// SOLUTION BEGIN
// Chapter 01, ray casting: the reference solution.
//
// This file is also the source of exercises/01_ray_casting.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 01, ray casting: your exercises.
// STUB //
// STUB // Each function below states what to compute (not how); its contract is documented in
// STUB // chapters/01_ray_casting/01_ray_casting.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_01
// STUB // Stuck? Hints in tiers you open one at a time: chapters/01_ray_casting/hints.md, or
// STUB // ./build/grade/hint 01.1 (tier 1, the idea), ./build/grade/hint 01.1 2 (the trap), ... 3 (the walk-through).
#include "01_ray_casting/01_ray_casting.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

namespace rt {

Ray primary_ray(const Camera& cam, float x, float y)
{
    // EXERCISE 01.1: the ray from the eye through pixel position (x, y).
    // Return the ray that leaves cam.eye through the point of the image window where the window
    // transform puts (x, y): columns from the left, rows from the top, pixel centres at whole numbers.
    // Any position counts, not only centres (x = -0.5 is the window's left edge). Its direction must be
    // unit length. Lesson: "Rays through pixel centres: the window transform".
    // Stuck? hint 01.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float us = cam.l + (cam.r - cam.l) * (x + 0.5f) / static_cast<float>(cam.nx);
    const float vs = cam.t - (cam.t - cam.b) * (y + 0.5f) / static_cast<float>(cam.ny);
    return Ray{cam.eye, glm::normalize(-cam.w + us * cam.u + vs * cam.v)};
    // SOLUTION END
    // STUB return stub("01.1", Ray{cam.eye, -cam.w});
}

std::optional<float> hit_plane(const Ray& ray, const Plane& plane, Interval range)
{
    // EXERCISE 01.2: where the ray meets the plane.
    // Return the ray's parameter t where it crosses `plane`, and only when t lies strictly inside
    // `range`. A ray parallel to the plane has no hit, and no division may decide that for you: never
    // a NaN or an infinity, not even for a ray that barely grazes the plane. The normal may face
    // either way. Lesson: "Where a ray meets a plane".
    // Stuck? hint 01.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    const float nv = glm::dot(plane.n, ray.dir);
    if (nv == 0.0f)
        return std::nullopt;
    const float t = glm::dot(plane.n, plane.b - ray.origin) / nv;
    // A ray that is nearly parallel can still overflow t to infinity; surrounds() rejects it
    // because range.max is at most infinity and the test is strict.
    if (!range.surrounds(t))
        return std::nullopt;
    return t;
    // SOLUTION END
    // STUB return stub("01.2", std::nullopt);
}

std::optional<Hit> closest_hit(const Ray& ray, const DiscScene& scene, Interval range)
{
    // EXERCISE 01.3: QueryScene, the nearest hit among the discs.
    // Return the hit record of the nearest disc the ray meets with t strictly inside `range`, whatever
    // the order of scene.discs; nothing when it meets none (an empty scene included). The given
    // hit_disc tests one disc and wants its index in the list. The interval can do the comparing.
    // Lesson: "QueryScene with an interval".
    // Stuck? hint 01.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    // SOLUTION BEGIN
    std::optional<Hit> closest;
    for (int k = 0; k < static_cast<int>(scene.discs.size()); ++k) {
        if (const std::optional<Hit> hit = hit_disc(ray, scene.discs[k], k, range)) {
            closest = hit;
            range.max = hit->t;
        }
    }
    return closest;
    // SOLUTION END
    // STUB return stub("01.3", std::nullopt);
}

}  // namespace rt
