#include "common/camera.hpp"
#include "common/error.hpp"
#include "tests/grader/graded.hpp"

using namespace rt;

TEST_CASE("the camera's basis is orthonormal, right-handed, with w pointing back from the view", "[common]")
{
    const Camera cam = make_camera({{1, 2, 3}, {-2, 0, 7}, {0.3f, 1, 0.1f}, 45.0f, 64, 48});
    const vec3 view = glm::normalize(vec3(-2, 0, 7) - vec3(1, 2, 3));
    INFO("u " << grader::show(cam.u) << ", v " << grader::show(cam.v) << ", w " << grader::show(cam.w));
    CHECK(glm::length(cam.w + view) <= 1e-6f);
    CHECK(std::abs(glm::dot(cam.u, cam.v)) <= 1e-6f);
    CHECK(std::abs(glm::dot(cam.u, cam.w)) <= 1e-6f);
    CHECK(std::abs(glm::length(cam.u) - 1.0f) <= 1e-6f);
    CHECK(glm::length(glm::cross(cam.u, cam.v) - cam.w) <= 1e-6f);
    CHECK(glm::dot(cam.v, vec3(0.3f, 1, 0.1f)) > 0.0f);  // v leans toward up
    CHECK(cam.t == Approx(std::tan(22.5 * grader::pi / 180.0)));
    CHECK(cam.r == Approx(cam.t * 64.0f / 48.0f));
    CHECK(cam.l == -cam.r);
    CHECK(cam.b == -cam.t);
}

TEST_CASE("an impossible camera is refused with a message naming the problem", "[common]")
{
    const CameraSpec good{{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 8, 8};
    struct Case {
        CameraSpec spec;
        const char* message;
    };
    std::vector<Case> cases;
    CameraSpec s = good;
    s.width = 0;
    cases.push_back({s, "image size must be at least 1x1"});
    s = good;
    s.vfov_degrees = 180.0f;
    cases.push_back({s, "field of view must lie strictly between 0 and 180"});
    s = good;
    s.vfov_degrees = 0.0f;
    cases.push_back({s, "field of view must lie strictly between 0 and 180"});
    s = good;
    s.at = s.from;
    cases.push_back({s, "looks from the point it looks at"});
    s = good;
    s.up = {0, 0, 2};
    cases.push_back({s, "up vector is parallel"});
    for (const Case& c : cases)
        CHECK_THROWS_WITH(make_camera(c.spec), rt::grader::contains_text(c.message));
}

TEST_CASE("a camera whose eye is 1e-29 from the point it looks at still looks there", "[common]")
{
    // |from - at|^2 is 1e-58: 0 in float, where glm::normalize would divide by it.
    const Camera cam = make_camera({{0, 0, 1e-29f}, {0, 0, 0}, {0, 1, 0}, 45.0f, 8, 8});
    INFO("w = " << rt::grader::show(cam.w) << ", u = " << rt::grader::show(cam.u));
    CHECK(cam.w == vec3(0, 0, 1));
    CHECK(cam.u == vec3(1, 0, 0));
    CHECK_THROWS_WITH(make_camera({{1e-29f, 0, 0}, {1e-29f, 0, 0}, {0, 1, 0}, 45.0f, 8, 8}),
                      rt::grader::contains_text("no view direction"));
}
