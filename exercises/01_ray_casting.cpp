// Chapter 01, ray casting: your exercises.
//
// Each function below states what to compute (not how); its contract is documented in
// chapters/01_ray_casting/01_ray_casting.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_01
// Stuck? Hints in tiers you open one at a time: chapters/01_ray_casting/hints.md, or
// ./build/grade/hint 01.1 (tier 1, the idea), ./build/grade/hint 01.1 2 (the trap), ... 3 (the walk-through).
#include "01_ray_casting/01_ray_casting.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

namespace rt {

Ray primary_ray(const Camera& cam, float x, float y)
{
    // EXERCISE 01.1: the ray from the eye through pixel position (x, y).
    // Return the ray that leaves cam.eye through the point of the image window where the window
    // transform puts (x, y): columns from the left, rows from the top, pixel centres at whole numbers.
    // Any position counts, not only centres (x = -0.5 is the window's left edge). Its direction must be
    // unit length. Lesson: "Rays through pixel centres: the window transform".
    // Stuck? hint 01.1 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("01.1", Ray{cam.eye, -cam.w});
}

std::optional<float> hit_plane(const Ray& ray, const Plane& plane, Interval range)
{
    // EXERCISE 01.2: where the ray meets the plane.
    // Return the ray's parameter t where it crosses `plane`, and only when t lies strictly inside
    // `range`. A ray parallel to the plane has no hit, and no division may decide that for you: never
    // a NaN or an infinity, not even for a ray that barely grazes the plane. The normal may face
    // either way. Lesson: "Where a ray meets a plane".
    // Stuck? hint 01.2 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("01.2", std::nullopt);
}

std::optional<Hit> closest_hit(const Ray& ray, const DiscScene& scene, Interval range)
{
    // EXERCISE 01.3: QueryScene, the nearest hit among the discs.
    // Return the hit record of the nearest disc the ray meets with t strictly inside `range`, whatever
    // the order of scene.discs; nothing when it meets none (an empty scene included). The given
    // hit_disc tests one disc and wants its index in the list. The interval can do the comparing.
    // Lesson: "QueryScene with an interval".
    // Stuck? hint 01.3 (tier 1: the idea; 2: the trap; 3: the walk-through)
    return stub("01.3", std::nullopt);
}

}  // namespace rt
