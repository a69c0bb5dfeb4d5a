// Chapter 06, depth of field: your exercises.
//
// Each function below says what to compute and gives a hint; its contract is documented in
// chapters/06_depth_of_field/06_depth_of_field.hpp and the lesson in that folder's README.md.
// Each stub compiles and returns a harmless value, so the chapter's program always runs.
// Check your work with:  cmake --build --preset grade --target check_06
//
// This chapter builds on chapter 01 (primary_ray, the pinhole ray, which 06.3 calls); its
// program and figure also use chapter 02's spheres and triangles and chapter 04's shading.
#include "06_depth_of_field/06_depth_of_field.hpp"
#include "common/stub.hpp"  // stub("NN.k", value) lets the program name unfinished exercises
#include "01_ray_casting/01_ray_casting.hpp"

#include <cmath>

namespace rt {

// pi / 4: the angle each eighth of a square ring (half of one side) spans on its circle.
[[maybe_unused]] constexpr float quarter_pi = 0.785398163397448309616f;  // the stub of 06.1 leaves it unused

point2 concentric_disc(point2 square)
{
    // EXERCISE 06.1: Shirley and Chiu's concentric map, unit square -> unit disc.
    // 1. Stretch [0, 1]^2 onto [-1, 1]^2: a = 2 square.x - 1, b = 2 square.y - 1.
    // 2. The centre (a = b = 0) has no angle: return (0, 0) before dividing by a or b.
    // 3. When |a| >= |b| (the left and right wedges): r = a, phi = (pi / 4) (b / a);
    //    otherwise (top and bottom): r = b, phi = pi / 2 - (pi / 4) (a / b).
    //    r keeps its sign, which puts the point in the opposite wedge when it is negative.
    // 4. Return (r cos phi, r sin phi).
    // Hint: quarter_pi is pi / 4; std::abs, std::cos and std::sin work on floats.
    return stub("06.1", point2(0.0f));
}

point3 focal_point(const Camera& cam, const ThinLens& lens, const Ray& pinhole)
{
    // EXERCISE 06.2: where the pinhole ray meets the plane of sharp focus.
    // The plane lies F = lens.focus_distance in front of the eye, along -w. A unit step along the
    // ray advances dir.(-w) toward it (the cosine of the ray's angle to the view direction), so the
    // ray reaches it at t = F / (dir.(-w)), not at t = F.
    // Hint: pinhole.at(t) is the point.
    return stub("06.2", pinhole.origin);
}

Ray thin_lens_ray(const Camera& cam, const ThinLens& lens, float x, float y, Rng& rng)
{
    // EXERCISE 06.3: the thin-lens ray through pixel position (x, y).
    // 1. The pinhole ray: primary_ray(cam, x, y). With lens.aperture_radius == 0, return it as it
    //    is, drawing nothing from rng (the lens formula below would round it differently).
    // 2. The lens sample: s.x = rng.next_float(), then s.y = rng.next_float(), in that order, and
    //    d = concentric_disc(s).
    // 3. The lens point: cam.eye + R (d.x cam.u + d.y cam.v), R = lens.aperture_radius: the lens
    //    lies in the camera's own u, v plane, whatever way the camera looks.
    // 4. The ray from the lens point toward focal_point(cam, lens, pinhole), direction made unit.
    return stub("06.3", Ray{cam.eye, -cam.w});
}

}  // namespace rt
