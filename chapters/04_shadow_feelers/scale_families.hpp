// Scenes a machine makes at every scale, held to a double reference: the numerics' counterpart of the
// grader's machine-made mutants. Each family (a floor under a near eye, a tilted ground with a
// sphere, a tessellated ball, a cluster beside a far sphere, a huge triangle over tiny ones, an eye
// inside a ball) is built at scale s = 10^k, moved 10^j from the origin, and seen from near or far.
// Every pixel's answer in float (chapter 04's closest_hit and shadow feelers, through brute force or
// a structure) is compared with the same float ray's answer worked out in double: which object, and
// which lights reach the point. A pixel that differs is explained when the double answer itself
// changes under float's resolution (the ray turned by a few ulps, the point moved by its t's
// rounding): an edge, a silhouette or a shadow's boundary that float cannot place. Any other
// difference is a wrong pixel, unless the scene is one float cannot hold and the kit says so
// (common/float_reach.hpp). The chapter's --sweep runs 990 such scenes into the lesson's table
// (04.scales); tests/structures/scale_sweep.cpp runs a sample in the test command.
#pragma once

#include "01_ray_casting/01_ray_casting.hpp"
#include "04_shadow_feelers/radiance.hpp"
#include "common/camera.hpp"
#include "common/error.hpp"
#include "common/float_reach.hpp"
#include "common/lesson_table.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rt::scale_families {

struct FamilyScene {
    LitScene scene;
    CameraSpec camera;
    std::string name;
};

// Where a family is placed: s its size, `out` its distance from the origin (along (1, 0.5, 0.7) for
// a solid, along the ground's plane for a ground), `far` how far the eye stands, in sizes.
struct Placement {
    double s = 1.0;
    double out = 0.0;
    double far = 1.0;
};

inline const std::vector<std::string>& family_names()
{
    static const std::vector<std::string> names = {"floor", "tilted ground", "ball", "cluster", "huge over tiny",
                                                   "inside a ball"};
    return names;
}

namespace detail {

inline point3 f(const dvec3& p) { return point3(p); }

inline void add_ball(LitScene& scene, const dvec3& centre, double r, int around, int down, int material)
{
    const auto corner = [&](int i, int j) {
        const double theta = 3.141592653589793 * j / down, phi = 6.283185307179586 * i / around;
        return centre + r * dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int j = 0; j < down; ++j)
        for (int i = 0; i < around; ++i) {
            const dvec3 a = corner(i, j), b = corner(i + 1, j), c = corner(i + 1, j + 1), d = corner(i, j + 1);
            if (j > 0)
                scene.add_triangle({f(a), f(c), f(b)}, material);
            if (j < down - 1)
                scene.add_triangle({f(a), f(d), f(c)}, material);
        }
}

}  // namespace detail

// The family `name` at placement `at`, with a square image `size` pixels across.
inline FamilyScene make_family(const std::string& name, const Placement& at, int size)
{
    using detail::f;
    FamilyScene out;
    LitScene& scene = out.scene;
    const int m = scene.add_material({});
    const double s = at.s;
    const dvec3 solid_at = at.out * glm::normalize(dvec3(1.0, 0.5, 0.7));
    const dvec3 ground_at = at.out * glm::normalize(dvec3(1.0, 0.0, 0.7));
    dvec3 look{0.0}, eye{0.0};
    if (name == "floor") {
        // A floor 1e6 s across; the eye s above it, the light 10 s above.
        const double w = 1e6 * s;
        scene.add_triangle({f(ground_at + dvec3(-w, 0, w)), f(ground_at + dvec3(w, 0, w)), f(ground_at + dvec3(0, 0, -w))}, m);
        look = ground_at + dvec3(3 * s, 0, -4 * s);
        eye = ground_at + dvec3(0, s, 0);
        scene.lights.push_back({f(ground_at + dvec3(s, 10 * s, -2 * s)), color(1.0f)});
    } else if (name == "tilted ground") {
        // A ground 1e4 s across, tilted off the axes, through the placement; a sphere of radius s on it.
        const dvec3 n = glm::normalize(dvec3(0.01, 1.0, 0.02));
        const auto on = [&](double x, double z) { return ground_at + dvec3(x, -(n.x * x + n.z * z) / n.y, z); };
        const double w = 1e4 * s;
        scene.add_triangle({f(on(-w, w)), f(on(w, w)), f(on(0, -w))}, m);
        scene.add_sphere({f(on(0, 0) + s * n), float(s)}, m);
        look = on(0, 0);
        eye = on(3 * s, 4 * s) + 3 * s * n;
        scene.lights.push_back({f(on(-2 * s, 1 * s) + 6 * s * n), color(1.0f)});
    } else if (name == "ball") {
        detail::add_ball(scene, solid_at, s, 24, 12, m);
        look = solid_at;
        eye = solid_at + dvec3(0.5 * s, 1.0 * s, 3.5 * s);
        scene.lights.push_back({f(solid_at + dvec3(3 * s, 4 * s, 2 * s)), color(1.0f)});
    } else if (name == "cluster") {
        // 125 spheres 0.01 s across in a box 0.1 s across, and one sphere of radius s 1e4 s away.
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j)
                for (int k = 0; k < 5; ++k)
                    scene.add_sphere({f(solid_at + 0.02 * s * dvec3(i - 2, j - 2, k - 2)), float(0.005 * s)}, m);
        scene.add_sphere({f(solid_at + dvec3(1e4 * s, 0, 0)), float(s)}, m);
        look = solid_at;
        eye = solid_at + dvec3(0.05 * s, 0.1 * s, 0.2 * s);
        scene.lights.push_back({f(solid_at + dvec3(0.3 * s, 0.4 * s, 0.1 * s)), color(1.0f)});
    } else if (name == "huge over tiny") {
        // One triangle 1e5 s across at y = 0, under 400 triangles 0.02 s across just above it.
        const double w = 1e5 * s;
        scene.add_triangle({f(ground_at + dvec3(-w, 0, w)), f(ground_at + dvec3(w, 0, w)), f(ground_at + dvec3(0, 0, -w))}, m);
        for (int i = 0; i < 20; ++i)
            for (int j = 0; j < 20; ++j) {
                const dvec3 c = ground_at + dvec3(0.03 * s * (i - 10), 0.002 * s * (1 + (i + j) % 3), 0.03 * s * (j - 10));
                scene.add_triangle({f(c), f(c + dvec3(0.02 * s, 0, 0)), f(c + dvec3(0, 0.001 * s, 0.02 * s))}, m);
            }
        look = ground_at;
        eye = ground_at + dvec3(0.1 * s, 0.3 * s, 0.4 * s);
        scene.lights.push_back({f(ground_at + dvec3(-0.2 * s, s, 0.1 * s)), color(1.0f)});
    } else {
        // The eye inside a ball of radius s, a light inside with it, a small sphere between.
        detail::add_ball(scene, solid_at, s, 24, 12, m);
        scene.add_sphere({f(solid_at + dvec3(0.3 * s, -0.5 * s, 0.1 * s)), float(0.2 * s)}, m);
        look = solid_at + dvec3(s, -s, 0);
        eye = solid_at + dvec3(-0.3 * s, 0.2 * s, 0);
        scene.lights.push_back({f(solid_at + dvec3(0.1 * s, 0.5 * s, 0.2 * s)), color(1.0f)});
    }
    // A far eye stands `far` times as far along the same line, with a field of view that keeps the
    // same picture.
    const dvec3 from = look + at.far * (eye - look);
    out.camera = CameraSpec{f(from), f(look), vec3(0, 1, 0), float(50.0 / at.far), size, size};
    out.name = name;
    return out;
}

// One pixel's answer: the object seen (-1: none) and, bit i, light i reaching the point.
struct Answer {
    int object = -1;
    unsigned lit = 0;
    bool operator==(const Answer& o) const { return object == o.object && lit == o.lit; }
    bool operator!=(const Answer& o) const { return !(*this == o); }
};

// The answer in float, as chapter 04 draws it: the scene's query (its accelerator, or brute force)
// and its feelers, from the hit's point and geometric normal, turned to the seen side.
inline Answer float_answer(const LitScene& scene, const Ray& ray)
{
    Answer a;
    const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
    if (!hit)
        return a;
    a.object = hit->object;
    const vec3 n = glm::dot(hit->ng, ray.dir) > 0.0f ? -hit->ng : hit->ng;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (glm::dot(n, scene.lights[i].position - hit->p) > 0.0f &&
            !light_blocked(scene, *hit, scene.lights[i].position, FeelerSettings{}))
            a.lit |= 1u << i;
    return a;
}

// The nearest object along a double ray with t in (t_min, t_max), every object but `skip`: ties to
// the lower number, as brute force breaks them. Its t goes to `t`.
inline int nearest_in_double(const LitScene& scene, const BasicRay<double>& ray, double t_min, double t_max, int skip,
                             double& t)
{
    int best = -1;
    t = t_max;
    const int spheres = static_cast<int>(scene.spheres.size());
    for (int k = 0; k < spheres + static_cast<int>(scene.triangles.size()); ++k) {
        if (k == skip)
            continue;
        std::optional<double> found;
        if (k < spheres) {
            const Sphere& sp = scene.spheres[k];
            found = hit_sphere_precise(ray, BasicSphere<double>{dvec3(sp.centre), double(sp.radius)},
                                       BasicInterval<double>{t_min, t});
        } else {
            const Triangle& tri = scene.triangles[k - spheres];
            const auto h = hit_triangle_watertight(ray, BasicTriangle<double>{dvec3(tri.a), dvec3(tri.b), dvec3(tri.c)},
                                                   BasicInterval<double>{t_min, t});
            if (h)
                found = h->t;
        }
        if (found && *found < t) {
            t = *found;
            best = k;
        }
    }
    return best;
}

// The answer in double for the ray from `o` along `d` (the float ray's own numbers), with the hit
// point moved `along` its distance (a rounding of t), and with `lift` moved off the surface as the
// robust offset moves it, before the feelers leave it. The objects are convex, so an object never shadows its
// own lit side: a feeler asks every other object.
inline Answer double_answer(const LitScene& scene, const dvec3& o, const dvec3& d, double along = 0.0, bool lift = false,
                            const dvec3& feeler_turn = dvec3(0.0))
{
    Answer a;
    double t = 0.0;
    a.object = nearest_in_double(scene, BasicRay<double>{o, d}, 0.0, std::numeric_limits<double>::infinity(), -1, t);
    if (a.object < 0)
        return a;
    dvec3 p = o + t * (1.0 + along) * d;
    const int spheres = static_cast<int>(scene.spheres.size());
    dvec3 n;
    if (a.object < spheres)
        n = glm::normalize(p - dvec3(scene.spheres[a.object].centre));
    else {
        const Triangle& tri = scene.triangles[a.object - spheres];
        n = glm::normalize(glm::cross(dvec3(tri.b) - dvec3(tri.a), dvec3(tri.c) - dvec3(tri.a)));
    }
    if (glm::dot(n, d) > 0.0)
        n = -n;
    if (lift) {
        // Where EXERCISE 04.3 starts the feelers, toward the first light: 256 float steps of each
        // coordinate times the normal's component along it (2^-16 near the origin).
        const point3 from(p);
        p = dvec3(offset_ray_origin(from, vec3(n), scene.lights[0].position - from));
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const dvec3 to = dvec3(scene.lights[i].position) - p;
        if (!(glm::dot(n, to) > 0.0))
            continue;
        const double distance = glm::length(to);
        const dvec3 dir = to / distance;
        double unused = 0.0;
        if (nearest_in_double(scene, BasicRay<double>{p, dir + feeler_turn * glm::max(glm::abs(dir), dvec3(0x1p-24))},
                              0.0, distance * (1.0 - shadow_epsilon),
                              a.object, unused) < 0)
            a.lit |= 1u << i;
    }
    return a;
}

// Does the double answer change within float's resolution of this ray? Its direction turned by
// `ulps` float steps on each axis, either way; its hit point moved by a relative 2^-20 along it (a
// few times the watertight test's rounding of t and the point's own); the feelers leaving from as
// far off the surface as the robust offset moves them (a shadow's edge that close to its occluder
// is the offset's, chapter 04's lesson); or the feelers' own directions turned by `ulps` steps.
inline bool within_resolution(const LitScene& scene, const Ray& ray, const Answer& reference)
{
    constexpr double ulps = 4.0, along = 0x1p-20;
    const dvec3 o(ray.origin), d(ray.dir);
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {-1.0, 1.0}) {
            dvec3 turned = d;
            turned[axis] += sign * ulps * std::numeric_limits<float>::epsilon() * std::max(std::abs(d[axis]), 0x1p-24);
            if (double_answer(scene, o, turned) != reference)
                return true;
        }
    if (double_answer(scene, o, d, along) != reference || double_answer(scene, o, d, -along) != reference ||
        double_answer(scene, o, d, 0.0, true) != reference)
        return true;
    for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {-1.0, 1.0}) {
            dvec3 turn(0.0);
            turn[axis] = sign * ulps * std::numeric_limits<float>::epsilon();
            if (double_answer(scene, o, d, 0.0, false, turn) != reference)
                return true;
        }
    return false;
}

// One scene's comparison: pixels whose float answer differs from double's, and of those the ones
// within float's resolution of a boundary (explained).
struct Comparison {
    int pixels = 0, differ = 0, explained = 0;
    std::string first;  // the first unexplained pixel, in words
    int wrong() const { return differ - explained; }
};

inline Comparison compare_with_double(const LitScene& scene, const Camera& cam)
{
    Comparison c;
    for (int y = 0; y < cam.ny; ++y)
        for (int x = 0; x < cam.nx; ++x) {
            const Ray ray = primary_ray(cam, x + 0.5f, y + 0.5f);
            ++c.pixels;
            const Answer got = float_answer(scene, ray);
            const Answer want = double_answer(scene, dvec3(ray.origin), dvec3(ray.dir));
            if (got == want)
                continue;
            ++c.differ;
            if (within_resolution(scene, ray, want)) {
                ++c.explained;
            } else if (c.first.empty()) {
                c.first = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): float sees object " +
                          std::to_string(got.object) + " lit " + std::to_string(got.lit) + ", double object " +
                          std::to_string(want.object) + " lit " + std::to_string(want.lit);
            }
        }
    return c;
}

// The kit's word on the scene and the view as float holds them (common/float_reach.hpp, what the
// NFF reader says of a file): empty when both are within float's reach.
inline std::string warning_for(const FamilyScene& f)
{
    std::vector<Box> boxes;
    for (const Sphere& sp : f.scene.spheres)
        boxes.push_back({sp.centre - vec3(sp.radius), sp.centre + vec3(sp.radius)});
    for (const Triangle& t : f.scene.triangles)
        boxes.push_back({glm::min(t.a, glm::min(t.b, t.c)), glm::max(t.a, glm::max(t.b, t.c))});
    const std::string scene = scene_beyond_float(boxes);
    return !scene.empty() ? scene : view_beyond_float(f.camera.from, f.camera.at, f.camera.vfov_degrees, f.camera.width);
}

// One scene of a run: where the family stood, what the comparison found, what the kit said.
struct Row {
    FamilyScene scene;
    Placement at;
    Comparison c;
    std::string warning;
};

// Every family at scales 10^k (k in `scales`), moved 10^j from the origin (j in `offsets`, -1 for
// not at all), seen from each of `fars` times its own distance; `size` pixels square.
inline std::vector<Row> run(const std::vector<int>& scales, const std::vector<int>& offsets,
                            const std::vector<double>& fars, int size)
{
    std::vector<Row> rows;
    for (const std::string& family : family_names())
        for (const int k : scales)
            for (const int j : offsets)
                for (const double far : fars) {
                    Row r;
                    r.at = Placement{std::pow(10.0, k), j < 0 ? 0.0 : std::pow(10.0, j), far};
                    r.scene = make_family(family, r.at, size);
                    r.warning = warning_for(r.scene);
                    try {
                        r.c = compare_with_double(r.scene.scene, make_camera(r.scene.camera));
                    } catch (const InputError& e) {
                        // Float rounds the eye onto the point it looks at: no picture to compare.
                        r.warning = e.what();
                    }
                    rows.push_back(std::move(r));
                }
    return rows;
}

// The sweep of the lesson: scales 10^-4 to 10^6, 0 and 1 to 10^6 from the origin, the eye at its
// own distance and 10^3 and 10^6 times it: 990 scenes of 24 x 24 pixels.
inline std::vector<Row> run_sweep()
{
    return run({-4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 6}, {-1, 0, 2, 4, 6}, {1.0, 1e3, 1e6}, 24);
}

// The rows by scale, as the lesson shows them.
inline LessonTable scales_table(const std::vector<Row>& rows)
{
    struct Sum {
        long long scenes = 0, warned = 0, pixels = 0, differ = 0, explained = 0, wrong = 0, wrong_warned = 0;
    };
    std::map<int, Sum> by_scale;
    for (const Row& r : rows) {
        Sum& s = by_scale[static_cast<int>(std::lround(std::log10(r.at.s)))];
        ++s.scenes;
        s.warned += r.warning.empty() ? 0 : 1;
        s.pixels += r.c.pixels, s.differ += r.c.differ, s.explained += r.c.explained;
        (r.warning.empty() ? s.wrong : s.wrong_warned) += r.c.wrong();
    }
    LessonTable t{"04.scales",
                  {{"s"}, {"scenes"}, {"warned"}, {"pixels"}, {"unlike double"}, {"explained"}, {"wrong"}, {"wrong, warned"}},
                  {},
                  "Every family at scale s, 0 to 1e6 from the origin, the eye near and 1e3 and 1e6 times as far; 24 x 24 "
                  "pixels a scene. wrong: unlike double, not explained, and no warning said."};
    for (const auto& [k, s] : by_scale)
        t.row({"1e" + std::to_string(k), grouped(s.scenes), grouped(s.warned), grouped(s.pixels), grouped(s.differ),
               grouped(s.explained), grouped(s.wrong), grouped(s.wrong_warned)});
    return t;
}

// A row a scene, for plots and for finding one scene again.
inline void write_rows_csv(std::ostream& out, const std::vector<Row>& rows)
{
    out << "family,scale,offset,far,pixels,differ,explained,wrong,warned\n";
    for (const Row& r : rows)
        out << '"' << r.scene.name << "\"," << r.at.s << ',' << r.at.out << ',' << r.at.far << ',' << r.c.pixels << ','
            << r.c.differ << ',' << r.c.explained << ',' << r.c.wrong() << ',' << (r.warning.empty() ? 0 : 1) << '\n';
}

}  // namespace rt::scale_families
