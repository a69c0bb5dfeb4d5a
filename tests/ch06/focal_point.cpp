// EXERCISE 06.2: where the pinhole ray meets the plane of sharp focus, F in front of the eye along -w.
#include "tests/ch06/describe.hpp"

using namespace rt;
using namespace rt::grader;

namespace {

// Float's rounding of eye + (F / cos) dir: a few units in the last place of the eye's coordinates
// and of the distance travelled; 1e-6 of their sum is about eight of them.
double tolerance(const Camera& cam, const dvec3& want)
{
    return 1e-6 * (glm::length(to_double(cam.eye)) + glm::length(want - to_double(cam.eye))) + 1e-12;
}

// Stops the case at the first point that is off: one failure says enough.
void check_focal_point(const Camera& cam, const ThinLens& lens, const Ray& pinhole, const std::string& what,
                       double allowed = -1.0)
{
    const point3 got = focal_point(cam, lens, pinhole);
    const dvec3 want = focal_point_reference(cam, lens.focus_distance, pinhole.dir);
    const double depth = glm::dot(to_double(got) - to_double(cam.eye), -to_double(cam.w));
    INFO(what << ": " << show(cam) << ", " << show(lens) << ", the pinhole " << show(pinhole) << ": focal_point gave "
         << show(got) << " (at depth " << depth << " along -w, " << glm::length(to_double(got - cam.eye))
         << " along the ray); expected " << show(vec3(want)) << " (at depth " << lens.focus_distance << ", "
         << glm::length(want - to_double(cam.eye)) << " along the ray)");
    if (allowed < 0.0)
        allowed = tolerance(cam, want);
    INFO("off by " << glm::length(to_double(got) - want) << ", allowed " << allowed);
    REQUIRE(glm::length(to_double(got) - want) <= allowed);
}

}  // namespace

GRADED_TEST("the ray straight ahead meets the plane of focus F in front of the eye", "06.2", 2)
{
    const Camera cam = make_camera(CameraSpec{{1, 2, 3}, {4, 2, -1}, {0, 1, 0}, 40.0f, 5, 3});
    for (const float focus : {0.5f, 3.0f, 250.0f})
        check_focal_point(cam, ThinLens{0.1f, focus}, Ray{cam.eye, -cam.w}, "the ray along -w");
}

GRADED_TEST("a slanted ray meets the plane at depth F along -w, which is F / cos(angle) along the ray, not F", "06.2", 3)
{
    Rng rng(6, 3);
    for (int k = 0; k < 200; ++k) {
        const Camera cam = random_camera(rng);
        const ThinLens lens{0.2f, 0.5f + 20.0f * rng.next_float()};
        // A ray through a random point of the window: up to the window's corners.
        const float us = cam.l + (cam.r - cam.l) * rng.next_float(), vs = cam.b + (cam.t - cam.b) * rng.next_float();
        const Ray pinhole{cam.eye, glm::normalize(-cam.w + us * cam.u + vs * cam.v)};
        check_focal_point(cam, lens, pinhole, "seeded case " + std::to_string(k));
    }
}

STABILITY_TEST("a 179-degree field of view, a plane 1e-4 or 1e5 away, and an eye 2.3e5 from the origin keep the point exact", "06.2", 2)
{
    // The window's corner at 179 degrees lies 114.6 units to the side of a window 1 unit away:
    // the corner ray advances only 0.0062 toward the plane per unit, and meets it 162 F away.
    const Camera wide = make_camera(CameraSpec{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 179.0f, 2, 2});
    const Ray corner{wide.eye, glm::normalize(-wide.w + wide.r * wide.u + wide.t * wide.v)};
    for (const float focus : {1e-4f, 1.0f, 1e5f})
        check_focal_point(wide, ThinLens{0.0f, focus}, corner, "the window's corner at 179 degrees");

    const Camera far = make_camera(CameraSpec{{1e5f, -2e5f, 3e4f}, {1e5f + 3, -2e5f + 1, 3e4f - 4}, {0, 1, 0}, 60.0f, 4, 4});
    const Ray slanted{far.eye, glm::normalize(-far.w + 0.4f * far.u - 0.3f * far.v)};
    for (const float focus : {1e-2f, 7.0f, 1e5f})
        check_focal_point(far, ThinLens{0.0f, focus}, slanted, "an eye 2.3e5 from the origin");
}

STABILITY_TEST("a 179-degree view from an eye 2.3e5 from the origin: the corner ray meets the plane 162 F away, exactly where t = F / (dir.(-w)) puts it", "06.2", 2)
{
    // Both extremes at once. Away from the origin the eye's coordinates are 1/64 apart in float;
    // a slanted ray multiplies any error in the depth it travels by 1 / (dir.(-w)) = 162. So the
    // depth must come from F itself, not from a point of the plane such as eye - F w, whose
    // rounding (up to 1/128 per coordinate) becomes an error of up to 0.6 in the point.
    // t = F / (dir.(-w)) in float is off by the rounding of the eye's coordinates in the sum
    // (half an ulp each) and t's own: the dot product's three roundings, relative to dir.(-w),
    // and two more; this case allows twice that, about 0.03 to 0.06 here.
    const Camera far_wide = make_camera(CameraSpec{{1e5f, -2e5f, 3e4f}, {1e5f + 3, -2e5f + 1, 3e4f - 4}, {0, 1, 0}, 179.0f, 2, 2});
    const double u = 0x1p-24, eye_ulp = 0x1p-6;  // float's unit roundoff; its spacing at 2e5
    for (const float side : {1.0f, -1.0f}) {
        const Ray corner{far_wide.eye, glm::normalize(-far_wide.w + side * far_wide.r * far_wide.u + far_wide.t * far_wide.v)};
        const double advance = glm::dot(to_double(corner.dir), -to_double(far_wide.w));
        for (const float focus : {0.01f, 0.37f, 1.0f, 3.0f}) {
            const double t = focus / advance;
            const double allowed = 2.0 * (t * (3.0 * u / advance + 2.0 * u) + eye_ulp);
            check_focal_point(far_wide, ThinLens{0.0f, focus}, corner,
                              "the window's corner at 179 degrees, the eye 2.3e5 from the origin", allowed);
        }
    }
}
