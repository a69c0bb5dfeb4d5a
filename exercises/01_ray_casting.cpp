// Chapter 01, ray casting: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/01_ray_casting/01_ray_casting.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_01
#include "01_ray_casting/01_ray_casting.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

namespace rt {

Ray primary_ray(const Camera& cam, float x, float y)
{
    // EXERCISE 01.1: the ray from the eye through pixel position (x, y).
    // Window transform: us = l + (r - l) (x + 0.5) / nx, and vs = t - (t - b) (y + 0.5) / ny
    // (rows count down from the top). The point (us, vs) on the window lies at
    // eye - w + us u + vs v, so the direction is -w + us u + vs v, made unit length.
    // Hint: glm::normalize makes a unit vector; the camera's fields are named as on the slide.
    return stub("01.1", Ray{cam.eye, -cam.w});
}

std::optional<float> hit_plane(const Ray& ray, const Plane& plane, Interval range)
{
    // EXERCISE 01.2: the plane n.(p - b) = 0 meets the ray p = u + v t at t = n.(b - u) / n.v.
    // When n.v is 0 the ray is parallel to the plane: no hit (and no division by zero).
    // Return t only when range.surrounds(t).
    // Hint: ray.origin is u, ray.dir is v; glm::dot is the dot product.
    return stub("01.2", std::nullopt);
}

std::optional<Hit> closest_hit(const Ray& ray, const DiscScene& scene, Interval range)
{
    // EXERCISE 01.3: QueryScene. Test every disc with hit_disc(ray, disc, index, range) and keep
    // the nearest hit.
    // Hint: after each hit, shrink range.max to its t: later discs then only count when nearer,
    // which is the slide's "if (object.distance < distance)".
    return stub("01.3", std::nullopt);
}

}  // namespace rt
