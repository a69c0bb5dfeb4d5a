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
