// SOLUTION BEGIN
// Chapter 01, ray casting: the reference solution.
//
// This file is also the source of exercises/01_ray_casting.cpp: the kit's cutter drops every
// block between SOLUTION BEGIN and SOLUTION END and keeps the STUB lines as code
// (`cmake --build <build> --target cut_exercises`; a test checks that the two agree).
// SOLUTION END
// STUB // Chapter 01, ray casting: your exercises.
// STUB //
// STUB // Each function below says what to compute and gives a hint; its contract is documented in
// STUB // chapters/01_ray_casting/01_ray_casting.hpp and the lesson in that folder's README.md.
// STUB // Each stub compiles and returns a harmless value, so the chapter's program always runs.
// STUB // Check your work with:  cmake --build --preset grade --target check_01
#include "01_ray_casting/01_ray_casting.hpp"
// STUB #include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises

namespace rt {

Ray primary_ray(const Camera& cam, float x, float y)
{
    // EXERCISE 01.1: the ray from the eye through pixel position (x, y).
    // Window transform: us = l + (r - l) (x + 0.5) / nx, and vs = t - (t - b) (y + 0.5) / ny
    // (rows count down from the top). The point (us, vs) on the window lies at
    // eye - w + us u + vs v, so the direction is -w + us u + vs v, made unit length.
    // Hint: glm::normalize makes a unit vector; the camera's fields are named as on the slide.
    // SOLUTION BEGIN
    const float us = cam.l + (cam.r - cam.l) * (x + 0.5f) / static_cast<float>(cam.nx);
    const float vs = cam.t - (cam.t - cam.b) * (y + 0.5f) / static_cast<float>(cam.ny);
    return Ray{cam.eye, glm::normalize(-cam.w + us * cam.u + vs * cam.v)};
    // SOLUTION END
    // STUB return stub("01.1", Ray{cam.eye, -cam.w});
}

std::optional<float> hit_plane(const Ray& ray, const Plane& plane, Interval range)
{
    // EXERCISE 01.2: the plane n.(p - b) = 0 meets the ray p = u + v t at t = n.(b - u) / n.v.
    // When n.v is 0 the ray is parallel to the plane: no hit (and no division by zero).
    // Return t only when range.surrounds(t).
    // Hint: ray.origin is u, ray.dir is v; glm::dot is the dot product.
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
    // EXERCISE 01.3: QueryScene. Test every disc with hit_disc(ray, disc, index, range) and keep
    // the nearest hit.
    // Hint: after each hit, shrink range.max to its t: later discs then only count when nearer,
    // which is the slide's "if (object.distance < distance)".
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
