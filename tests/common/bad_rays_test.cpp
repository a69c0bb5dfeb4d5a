// Rays that are no rays at all (a NaN or an infinite component, a zero direction) fed to every
// intersection routine of the kit's reference solutions and to every accelerator: never a hit,
// never a NaN out, never a hang.
#include "01_ray_casting/01_ray_casting.hpp"
#include "02_spheres_triangles/02_spheres_triangles.hpp"
#include "02_spheres_triangles/cone.hpp"
#include "02_spheres_triangles/scene_query.hpp"
#include "tests/grader/graded.hpp"

#include <limits>
#include <vector>

using namespace rt;
using rt::grader::show;

namespace {

constexpr float nan = std::numeric_limits<float>::quiet_NaN();

// Each bad component put in each place of a ray aimed at the shapes below, and the zero direction.
std::vector<Ray> bad_rays()
{
    std::vector<Ray> rays;
    const Ray good{{0.1f, 0.2f, -5.0f}, {0.0f, 0.0f, 1.0f}};
    for (const float bad : {nan, infinity, -infinity})
        for (int i = 0; i < 6; ++i) {
            Ray r = good;
            (i < 3 ? r.origin[i] : r.dir[i - 3]) = bad;
            rays.push_back(r);
        }
    rays.push_back({good.origin, vec3(0.0f)});
    rays.push_back({vec3(nan), vec3(nan)});
    return rays;
}

template <class T>
void check_none(const std::optional<T>& got, const Ray& ray, const char* what)
{
    INFO(what << " for the bad " << show(ray) << ": got " << (got ? "a hit" : "no hit") << ", expected no hit");
    CHECK(!got);
}

}  // namespace

TEST_CASE("a NaN, infinite or zero ray hits no plane, sphere, triangle or cone, in float or double")
{
    const Interval all{0.0f, infinity};
    const Sphere sphere{{0, 0, 0}, 1.0f};
    const Triangle tri{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const Cone cone{{0, -1, 0}, 1.0f, {0, 1, 0}, 0.5f};
    const Plane plane{{0, 0, 0}, {0, 0, -1}};
    for (const Ray& ray : bad_rays()) {
        check_none(hit_plane(ray, plane, all), ray, "hit_plane");
        check_none(hit_sphere_slide(ray, sphere, all), ray, "hit_sphere_slide");
        check_none(hit_sphere_precise(ray, sphere, all), ray, "hit_sphere_precise");
        check_none(hit_triangle_slide(ray, tri, all), ray, "hit_triangle_slide");
        check_none(hit_triangle_moller_trumbore(ray, tri, all), ray, "hit_triangle_moller_trumbore");
        check_none(hit_triangle_watertight(ray, tri, all), ray, "hit_triangle_watertight");
        check_none(hit_cone(ray, cone, all), ray, "hit_cone");
        const BasicRay<double> d{dvec3(ray.origin), dvec3(ray.dir)};
        const BasicInterval<double> dall{0.0, std::numeric_limits<double>::infinity()};
        check_none(hit_sphere_slide(d, BasicSphere<double>{dvec3(0.0), 1.0}, dall), ray, "hit_sphere_slide<double>");
        check_none(hit_sphere_precise(d, BasicSphere<double>{dvec3(0.0), 1.0}, dall), ray, "hit_sphere_precise<double>");
        const BasicTriangle<double> dtri{dvec3(tri.a), dvec3(tri.b), dvec3(tri.c)};
        check_none(hit_triangle_slide(d, dtri, dall), ray, "hit_triangle_slide<double>");
        check_none(hit_triangle_moller_trumbore(d, dtri, dall), ray, "hit_triangle_moller_trumbore<double>");
        check_none(hit_triangle_watertight(d, dtri, dall), ray, "hit_triangle_watertight<double>");
        std::vector<Sphere> spheres{sphere};
        Objects o;
        o.spheres = spheres.data();
        o.sphere_count = 1;
        ObjectHit hit;
        INFO("brute force's queries for the bad " << show(ray));
        CHECK(!brute_force().closest(ray, all, o, hit));
        CHECK(!brute_force().any(ray, all, o));
    }
}
