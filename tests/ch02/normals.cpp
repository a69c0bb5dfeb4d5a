// EXERCISE 02.6: normals, the sphere's and the interpolated one of a smooth-shaded triangle.
#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "tests/ch02/describe.hpp"

#include <cmath>

using namespace rt;
using namespace rt::grader;

GRADED_TEST("sphere_normal: unit length, pointing from the centre through the point", "02.6", 2)
{
    const Sphere sphere{{1, -2, 3}, 2};
    for (const vec3 towards : {vec3(1, 0, 0), vec3(0, -1, 0), glm::normalize(vec3(-1, 2, -2)), glm::normalize(vec3(3, 1, 0.5f))}) {
        const point3 p = sphere.centre + sphere.radius * towards;
        const vec3 n = sphere_normal(sphere, p);
        INFO(show(sphere) << ", the point " << show(p) << " on it: got the normal " << show(n) << ", expected "
             << show(towards));
        CHECK(std::abs(glm::length(n) - 1.0f) <= 1e-6f);
        CHECK(glm::length(n - towards) <= 1e-6f);
    }
}

STABILITY_TEST("sphere_normal: unit length on a sphere 1e4 away, though the hit point is rounded there", "02.6", 1)
{
    // At 1e4 a float point is 2^-10 from its neighbours: (p - O) / r is then up to about 1e-3 off
    // unit length for a unit sphere; the normal must not be.
    const Sphere sphere{{1e4f, 3e3f, -2e3f}, 1.0f};
    Rng rng(16, 0);
    for (int k = 0; k < 1000; ++k) {
        const point3 p = sphere.centre + extremes::random_unit_vector(rng);
        const vec3 n = sphere_normal(sphere, p);
        INFO(show(sphere) << ", the point " << show(p) << ": got the normal " << show(n) << " of length " << glm::length(n));
        REQUIRE(std::abs(glm::length(n) - 1.0f) <= 1e-6f);
        REQUIRE(glm::dot(n, p - sphere.centre) > 0.0f);
    }
}

GRADED_TEST("interpolated_normal: each corner's own normal at the corners, unit length in between", "02.6", 2)
{
    const CornerNormals normals{glm::normalize(vec3(0, 0, 1)), glm::normalize(vec3(1, 0, 1)), glm::normalize(vec3(0, 1, 1))};
    struct Case {
        float beta, gamma;
        vec3 expected;
    };
    const vec3 centroid = glm::normalize(normals.a + normals.b + normals.c);
    for (const Case& c : {Case{0, 0, normals.a}, Case{1, 0, normals.b}, Case{0, 1, normals.c},
                          Case{1.0f / 3, 1.0f / 3, centroid}}) {
        const vec3 n = interpolated_normal(normals, TriangleHit<float>{1.0f, c.beta, c.gamma});
        INFO("corner normals a " << show(normals.a) << ", b " << show(normals.b) << ", c " << show(normals.c)
             << " at beta = " << c.beta << ", gamma = " << c.gamma << ": got " << show(n) << ", expected " << show(c.expected));
        CHECK(std::abs(glm::length(n) - 1.0f) <= 1e-6f);
        CHECK(glm::length(n - c.expected) <= 1e-6f);
    }
}

GRADED_TEST("interpolated_normal: across a sharp fold (corner normals nearly opposite), the short weighted sum, made unit, is within 1e-5 of double", "02.6", 1)
{
    // Corners a and b have normals 179.9 degrees apart: halfway along edge a-b (beta = 0.5, gamma = 0)
    // their weighted sum is 2e-4 long, so the weights must be exact there: alpha = 1 - beta - gamma
    // is 0.5 with no rounding, and any error in it (a float step, 1.2e-7) lands on a vector 2000
    // times shorter than the normals and turns the answer by about 1e-4.
    const CornerNormals normals{vec3(1, 0, 0), glm::normalize(vec3(-1, 0x1p-11f, 0)), vec3(0, 0, 1)};
    for (const auto& [beta, gamma] : {std::pair{0.5f, 0.0f}, std::pair{0.5f, 0x1p-20f}}) {
        const TriangleHit<float> hit{1.0f, beta, gamma};
        const vec3 got = interpolated_normal(normals, hit);
        const double alpha = 1.0 - double(beta) - double(gamma);
        const dvec3 sum = alpha * dvec3(normals.a) + double(beta) * dvec3(normals.b) + double(gamma) * dvec3(normals.c);
        const dvec3 want = sum / glm::length(sum);
        INFO("corner normals a = " << show(normals.a) << ", b = " << show(normals.b) << ", c = " << show(normals.c)
             << ", beta = " << beta << ", gamma = " << gamma << ": got " << show(got) << ", expected (" << want.x << ", "
             << want.y << ", " << want.z << ") from the weights 1 - beta - gamma, beta, gamma in double");
        CHECK(glm::length(dvec3(got) - want) <= 1e-5);
    }
}
