// EXERCISE 01.1: primary rays through the window transform.
#include "01_ray_casting/01_ray_casting.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>

using namespace rt;
using rt::grader::show;

namespace {

Camera camera(point3 from, point3 at, vec3 up, float vfov, int nx, int ny)
{
    return make_camera(CameraSpec{from, at, up, vfov, nx, ny});
}

// The eye at the origin looking down -z with y up; a 90 degree field of view puts the window's
// top at t = 1, and a 4x2 image makes it twice as wide: [l, r] x [b, t] = [-2, 2] x [-1, 1].
Camera canonical_4x2() { return camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0f, 4, 2); }

// Checks that `ray` starts at `eye` and runs along the unit vector of `towards`.
void check_ray(const Ray& ray, const point3& eye, const vec3& towards, const std::string& what)
{
    const vec3 expected = glm::normalize(towards);
    INFO(what << ": got " << show(ray) << "; expected a ray from " << show(eye) << " along " << show(expected));
    CHECK(glm::length(ray.origin - eye) <= 1e-6f * (1.0f + glm::length(eye)));
    CHECK(std::abs(glm::length(ray.dir) - 1.0f) <= 1e-6f);
    CHECK(glm::length(ray.dir - expected) <= 2e-6f);
}

}  // namespace

GRADED_TEST("the centre pixel's ray points at the target, and its neighbours lean away from it", "01.1", 2)
{
    const point3 from{1, 2, 3}, at{4, 2, -1};  // looking along (3, 0, -4) / 5
    const Camera cam = camera(from, at, {0, 1, 0}, 40.0f, 5, 3);
    check_ray(primary_ray(cam, 2, 1), from, at - from, "5x3 image, centre pixel (2, 1)");
    const auto lean = [&](float x, float y) { return primary_ray(cam, x, y).dir; };
    INFO("pixel (1, 1) is left of centre, (3, 1) right of it, (2, 0) above (row 0 is the top), (2, 2) below");
    CHECK(glm::dot(lean(1, 1), cam.u) < 0.0f);
    CHECK(glm::dot(lean(3, 1), cam.u) > 0.0f);
    CHECK(glm::dot(lean(2, 0), cam.v) > 0.0f);
    CHECK(glm::dot(lean(2, 2), cam.v) < 0.0f);
}

GRADED_TEST("a pixel's ray passes through the centre of that pixel on the window", "01.1", 3)
{
    // Pixel (0, 0) covers [-2, -1] x [0, 1] of the window; its centre is (-1.5, 0.5).
    const Camera cam = canonical_4x2();
    check_ray(primary_ray(cam, 0, 0), cam.eye, {-1.5f, 0.5f, -1.0f}, "4x2 image, 90 degrees, pixel (0, 0)");
    check_ray(primary_ray(cam, 3, 1), cam.eye, {1.5f, -0.5f, -1.0f}, "4x2 image, 90 degrees, pixel (3, 1)");
    check_ray(primary_ray(cam, 1, 0), cam.eye, {-0.5f, 0.5f, -1.0f}, "4x2 image, 90 degrees, pixel (1, 0)");
}

GRADED_TEST("sample positions between pixel centres map linearly, out to the window's edges", "01.1", 2)
{
    // x = -0.5 is the left edge of the image and y = -0.5 its top edge: the window's corner (l, t).
    const Camera cam = canonical_4x2();
    check_ray(primary_ray(cam, -0.5f, -0.5f), cam.eye, {-2.0f, 1.0f, -1.0f}, "4x2 image, position (-0.5, -0.5)");
    check_ray(primary_ray(cam, 3.5f, 1.5f), cam.eye, {2.0f, -1.0f, -1.0f}, "4x2 image, position (3.5, 1.5)");
    check_ray(primary_ray(cam, 1.25f, 0.75f), cam.eye, {-0.25f, -0.25f, -1.0f}, "4x2 image, position (1.25, 0.75)");
}

GRADED_TEST("an arbitrary viewpoint builds the ray from the camera's u, v, w basis", "01.1", 2)
{
    // Looking along +x with z up: right is -y, so the top-left pixel leans toward +y and +z.
    const point3 from{10, -3, 2};
    const Camera cam = camera(from, {11, -3, 2}, {0, 0, 1}, 90.0f, 2, 2);
    check_ray(primary_ray(cam, 0, 0), from, {1.0f, 0.5f, 0.5f}, "eye (10, -3, 2) looking along +x, z up, pixel (0, 0)");
    check_ray(primary_ray(cam, 1, 1), from, {1.0f, -0.5f, -0.5f}, "eye (10, -3, 2) looking along +x, z up, pixel (1, 1)");
}

STABILITY_TEST("fields of view of 1 and 179 degrees give unit rays that reach the window's edge", "01.1", 2)
{
    for (const float vfov : {1.0f, 179.0f}) {
        const Camera cam = camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, vfov, 9, 9);
        const Ray centre = primary_ray(cam, 4, 4);
        const Ray top = primary_ray(cam, 4, -0.5f);  // the middle of the window's top edge
        const double angle = std::acos(std::clamp(double(glm::dot(centre.dir, top.dir)), -1.0, 1.0)) * 180.0 / rt::grader::pi;
        INFO("vertical field of view " << vfov << " degrees, 9x9 image: centre " << show(centre) << ", top edge "
             << show(top) << ", angle between them " << angle << " degrees, expected " << vfov / 2);
        CHECK(std::isfinite(top.dir.x + top.dir.y + top.dir.z));
        CHECK(std::abs(glm::length(top.dir) - 1.0f) <= 1e-6f);
        CHECK(std::abs(angle - vfov / 2.0) <= 1e-3);
    }
}

STABILITY_TEST("a 1x1 image looks straight ahead, and a 4096x1 image fans out symmetrically", "01.1", 2)
{
    const Camera one = camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 1, 1);
    check_ray(primary_ray(one, 0, 0), one.eye, {0, 0, -1}, "1x1 image, its one pixel");

    const Camera wide = camera({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 4096, 1);
    const Ray left = primary_ray(wide, 0, 0), right = primary_ray(wide, 4095, 0);
    INFO("4096x1 image: pixel 0 " << show(left) << ", pixel 4095 " << show(right));
    CHECK(std::abs(glm::length(left.dir) - 1.0f) <= 1e-6f);
    CHECK(left.dir.x < -0.99f);  // the window is 4096 times wider than high: nearly sideways
    CHECK(std::abs(left.dir.x + right.dir.x) <= 1e-6f);
    CHECK(std::abs(left.dir.y - right.dir.y) <= 1e-6f);
}

GRADED_TEST("a window whose left and top edges are 0: x = -0.5 lands exactly on l and y = -0.5 exactly on t", "01.1", 2)
{
    // The window [l, r] x [b, t] = [0, 2] x [-2, 0], straight down -z: x = -0.5 is l + (r - l) x 0,
    // which is 0 exactly, so the ray through the left edge has no sideways part at all; y = -0.5 is
    // t, 0 exactly, so the ray through the top edge has no upward part. A pixel centre put at
    // anything but x + 0.5 (even one float step past a half) leans the edge's ray off the window.
    const Camera cam{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.0f, 2.0f, -2.0f, 0.0f, 2, 2};
    const Ray left = primary_ray(cam, -0.5f, 1.5f);   // the window's bottom-left corner (l, b)
    const Ray top = primary_ray(cam, 1.5f, -0.5f);    // its top-right corner (r, t)
    INFO("window [l, r] x [b, t] = [0, 2] x [-2, 0], 2x2 image, eye at the origin looking down -z: position (-0.5, 1.5) gave "
         << show(left) << ", expected a direction along (0, -2, -1) with x exactly 0; position (1.5, -0.5) gave "
         << show(top) << ", expected a direction along (2, 0, -1) with y exactly 0");
    CHECK(left.dir.x == 0.0f);
    CHECK(top.dir.y == 0.0f);
    check_ray(left, cam.eye, {0.0f, -2.0f, -1.0f}, "window [0, 2] x [-2, 0], position (-0.5, 1.5)");
    check_ray(top, cam.eye, {2.0f, 0.0f, -1.0f}, "window [0, 2] x [-2, 0], position (1.5, -0.5)");
}
