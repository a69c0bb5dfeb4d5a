// The extreme cases where the chapter's formulas break (distant, tiny and huge spheres; rays aimed at
// a mesh's shared edges and vertices; degenerate triangles) as rays and shapes, and how a test's answers on them are scored
// against the exact ones (exact.hpp). The stability tests assert on these scores; the program's
// trade table (--sweep) prints them for every test in float and in double.
//
// Every case is made from float numbers (the scene's), then each ray's direction is made unit in
// the precision under test: a double test gets a double-unit direction, as a double renderer would.
// Cases are seeded, so a run repeats exactly.
#pragma once

#include "02_spheres_triangles/exact.hpp"
#include "02_spheres_triangles/mesh_scene.hpp"
#include "common/random.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace rt::extremes {

constexpr float two_pi = 6.28318530718f;

inline vec3 random_unit_vector(Rng& rng)
{
    const float z = 2.0f * rng.next_float() - 1.0f, phi = two_pi * rng.next_float();
    const float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

// Uniform over the disc of radius `radius` perpendicular to the unit vector `axis`.
inline vec3 random_in_disc(Rng& rng, const vec3& axis, float radius)
{
    const vec3 helper = std::abs(axis.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0);
    const vec3 s = glm::normalize(glm::cross(axis, helper)), t = glm::cross(axis, s);
    const float r = radius * std::sqrt(rng.next_float()), phi = two_pi * rng.next_float();
    return r * std::cos(phi) * s + r * std::sin(phi) * t;
}

// A ray from `from` toward `to`, its direction made unit in T.
template <class T>
BasicRay<T> ray_towards(const point3& from, const point3& to)
{
    return BasicRay<T>{vec3_t<T>(from), glm::normalize(vec3_t<T>(to) - vec3_t<T>(from))};
}

// --- Spheres ---

template <class T>
struct SphereProbe {
    BasicRay<T> ray;
    BasicSphere<T> sphere;
};

// The lesson's setup for distant spheres: a sphere of radius r whose centre lies at distance D from an eye at the
// origin, in a random direction, and a ray aimed at a random point within 1.2 r of the centre
// (on the disc facing the eye): about 69% of the rays hit.
template <class T>
std::vector<SphereProbe<T>> distant_spheres(float distance, float radius, int count, std::uint64_t seed)
{
    Rng rng(seed, 2);
    std::vector<SphereProbe<T>> probes;
    for (int k = 0; k < count; ++k) {
        const vec3 towards = random_unit_vector(rng);
        const point3 centre = distance * towards;
        const point3 target = centre + random_in_disc(rng, towards, 1.2f * radius);
        probes.push_back({ray_towards<T>(point3(0.0f), target), {vec3_t<T>(centre), T(radius)}});
    }
    return probes;
}

// A sphere of radius 1e4 seen from 1 unit above its surface, rays in every direction: those that
// dip below the horizon hit. Its c = |f|^2 - r^2 still cancels: two numbers of size 1e8 whose
// difference is of size 1e4. The centre sits off the float grid's round numbers, so that
// f = E - O is not exact in float either (at (0, -1e4, 0) it was, and hid that rounding).
template <class T>
std::vector<SphereProbe<T>> huge_sphere(int count, std::uint64_t seed)
{
    constexpr float radius = 1e4f;
    Rng rng(seed, 3);
    std::vector<SphereProbe<T>> probes;
    const point3 centre{3.3f, 0.7f - radius, -2.1f};
    for (int k = 0; k < count; ++k) {
        const point3 eye = centre + (radius + 1.0f) * random_unit_vector(rng);
        probes.push_back({ray_towards<T>(eye, eye + random_unit_vector(rng)), {vec3_t<T>(centre), T(radius)}});
    }
    return probes;
}

// Rays that start inside a sphere of radius 1 (anywhere up to 0.999 of the way to its surface)
// and run in every direction: every one hits, on the far side.
template <class T>
std::vector<SphereProbe<T>> inside_sphere(int count, std::uint64_t seed)
{
    Rng rng(seed, 4);
    std::vector<SphereProbe<T>> probes;
    const point3 centre{0.5f, -1.0f, 2.0f};
    for (int k = 0; k < count; ++k) {
        const point3 eye = centre + 0.999f * std::cbrt(rng.next_float()) * random_unit_vector(rng);
        probes.push_back({ray_towards<T>(eye, eye + random_unit_vector(rng)), {vec3_t<T>(centre), T(1)}});
    }
    return probes;
}

// --- Triangles ---

template <class T>
struct TriangleProbes {
    enum class Expect {
        exact,     // hit or miss as the exact answer says, tested against one triangle
        some_hit,  // aimed at a shared vertex or edge, or from inside a closed mesh: one must hit
        no_hit,    // degenerate triangles: none may be hit
    };
    Expect expect = Expect::exact;
    std::vector<BasicTriangle<T>> triangles;
    std::vector<BasicRay<T>> rays;
    std::vector<std::vector<int>> targets;  // per ray, the triangles it is tested against; empty: all

    void add(const BasicRay<T>& ray, std::vector<int> against)
    {
        rays.push_back(ray);
        targets.push_back(std::move(against));
    }
};

template <class T>
BasicTriangle<T> in_precision(const Triangle& t)
{
    return {vec3_t<T>(t.a), vec3_t<T>(t.b), vec3_t<T>(t.c)};
}

// Probes against the faces of `mesh`, expecting `expect`, with no rays yet.
template <class T>
TriangleProbes<T> probes_on(const IndexedMesh& mesh, typename TriangleProbes<T>::Expect expect)
{
    TriangleProbes<T> probes;
    probes.expect = expect;
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
        probes.triangles.push_back(in_precision<T>(triangle_of(mesh, f)));
    return probes;
}

// A closed mesh whose edges lie along no axis and no symmetry: an icosphere of 320 faces with
// every vertex moved by up to 2% of its radius.
inline IndexedMesh jittered_icosphere(std::uint64_t seed)
{
    IndexedMesh mesh = icosphere({0.3f, -0.2f, 0.1f}, 1.0f, 2);
    Rng rng(seed, 5);
    jitter(mesh, 0.02f, rng);
    return mesh;
}

// An origin 3 units out from `target`, within about 30 degrees of the outward direction, so the
// ray crosses the surface there rather than grazing it.
inline point3 origin_facing(Rng& rng, const point3& target, const vec3& outward)
{
    return target + 3.0f * glm::normalize(outward + 0.5f * random_unit_vector(rng));
}

// Rays aimed exactly at the mesh's vertices, each tested against the faces around its vertex.
template <class T>
TriangleProbes<T> vertex_aimed(const IndexedMesh& mesh, int rays_per_vertex, std::uint64_t seed)
{
    TriangleProbes<T> probes = probes_on<T>(mesh, TriangleProbes<T>::Expect::some_hit);
    Rng rng(seed, 6);
    for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
        std::vector<int> fan;
        for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
            if (std::find(mesh.faces[f].begin(), mesh.faces[f].end(), v) != mesh.faces[f].end())
                fan.push_back(f);
        for (int k = 0; k < rays_per_vertex; ++k)
            probes.add(ray_towards<T>(origin_facing(rng, mesh.vertices[v], mesh.normals[v]), mesh.vertices[v]), fan);
    }
    return probes;
}

// Rays aimed at points of the mesh's edges (a + s (b - a) rounded to float, which lies within
// rounding of the edge), each tested against the two faces that share the edge.
template <class T>
TriangleProbes<T> edge_aimed(const IndexedMesh& mesh, int rays_per_edge, std::uint64_t seed)
{
    TriangleProbes<T> probes = probes_on<T>(mesh, TriangleProbes<T>::Expect::some_hit);
    Rng rng(seed, 7);
    for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
        for (int e = 0; e < 3; ++e) {
            const int i = mesh.faces[f][e], j = mesh.faces[f][(e + 1) % 3];
            if (i > j)
                continue;  // each edge once: from the face that runs along it from lower to higher
            int other = -1;
            for (int g = 0; g < static_cast<int>(mesh.faces.size()); ++g)
                for (int h = 0; h < 3; ++h)
                    if (mesh.faces[g][h] == j && mesh.faces[g][(h + 1) % 3] == i)
                        other = g;
            for (int k = 0; k < rays_per_edge; ++k) {
                const float s = 0.05f + 0.9f * rng.next_float();
                const point3 target = mesh.vertices[i] + s * (mesh.vertices[j] - mesh.vertices[i]);
                const vec3 outward = glm::normalize(mesh.normals[i] + mesh.normals[j]);
                probes.add(ray_towards<T>(origin_facing(rng, target, outward), target), {f, other});
            }
        }
    return probes;
}

// Embree's own watertightness check, made harder: a closed sphere of 1280 triangles far from the
// origin, at (148376, 1234, -223423) where float steps are 1/64, its vertices jittered by up to 1%
// of its radius, and rays from its centre aimed at its vertices and at points of its edges. From
// inside a closed mesh every ray must hit.
template <class T>
TriangleProbes<T> inside_far_mesh(int count, std::uint64_t seed)
{
    const point3 centre{148376.0f, 1234.0f, -223423.0f};
    IndexedMesh mesh = icosphere(centre, 100.0f, 3);
    Rng rng(seed, 8);
    jitter(mesh, 1.0f, rng);
    TriangleProbes<T> probes = probes_on<T>(mesh, TriangleProbes<T>::Expect::some_hit);
    const int faces = static_cast<int>(mesh.faces.size());
    for (int k = 0; k < count; ++k) {
        const Triangle t = triangle_of(mesh, std::min(faces - 1, static_cast<int>(rng.next_float() * static_cast<float>(faces))));
        const point3 target = k % 2 ? t.a : t.a + rng.next_float() * (t.b - t.a);  // a vertex, or a point of an edge
        probes.add(ray_towards<T>(centre, target), {});
    }
    return probes;
}

// Rays from all around aimed at random points of a random face's plane, up to a quarter of the
// face beyond its edges: about half hit.
template <class T>
TriangleProbes<T> around_triangles(const IndexedMesh& mesh, int count, std::uint64_t seed)
{
    TriangleProbes<T> probes = probes_on<T>(mesh, TriangleProbes<T>::Expect::exact);
    Rng rng(seed, 9);
    const int faces = static_cast<int>(mesh.faces.size());
    for (int k = 0; k < count; ++k) {
        const int f = std::min(faces - 1, static_cast<int>(rng.next_float() * static_cast<float>(faces)));
        const Triangle t = triangle_of(mesh, f);
        const float beta = 1.5f * rng.next_float() - 0.25f, gamma = 1.5f * rng.next_float() - 0.25f;
        const point3 target = t.a + beta * (t.b - t.a) + gamma * (t.c - t.a);
        probes.add(ray_towards<T>(target + 3.0f * random_unit_vector(rng), target), {f});
    }
    return probes;
}

// Triangles without area, which must never be hit: all corners equal, two equal, collinear along
// an axis or a diagonal, and pbrt-v4's BadCase (shapes_test.cpp), a sliver that a watertight test
// without a degeneracy check once hit. Rays aimed at their corners and midpoints.
inline std::vector<Triangle> degenerate_triangles()
{
    const point3 p{0.25f, -0.5f, 1.0f}, q{1.5f, 0.75f, -0.5f};
    return {
        {p, p, p},
        {p, p, q},
        {p, q, q},
        {q, p, q},
        {{1, 2, 3}, {2, 4, 6}, {3, 6, 9}},
        {{0, 0, 0}, {0, 3, 0}, {0, 1, 0}},
        {{-1113.45459f, -79.049614f, -56.2431908f}, {-1113.45459f, -87.0922699f, -56.2431908f},
         {-1113.45459f, -79.2090149f, -56.2431908f}},
    };
}

template <class T>
TriangleProbes<T> degenerate(int rays_per_target, std::uint64_t seed)
{
    TriangleProbes<T> probes;
    probes.expect = TriangleProbes<T>::Expect::no_hit;
    Rng rng(seed, 10);
    const std::vector<Triangle> tris = degenerate_triangles();
    for (int f = 0; f < static_cast<int>(tris.size()); ++f) {
        const Triangle& t = tris[f];
        probes.triangles.push_back(in_precision<T>(t));
        const float size = 1.0f + glm::length(t.b - t.a) + glm::length(t.c - t.a);
        for (const point3& target : {t.a, t.b, t.c, 0.5f * (t.a + t.b), 0.5f * (t.b + t.c), (t.a + t.b + t.c) / 3.0f})
            for (int k = 0; k < rays_per_target; ++k)
                probes.add(ray_towards<T>(target + 3.0f * size * random_unit_vector(rng), target), {f});
    }
    return probes;
}

// --- Running a test on a case, and scoring its answers ---

// A sphere test's answers, one per probe.
template <class T, class Test>
void run(const std::vector<SphereProbe<T>>& probes, const Test& test, std::vector<std::optional<T>>& answers)
{
    answers.resize(probes.size());
    for (size_t k = 0; k < probes.size(); ++k)
        answers[k] = test(probes[k].ray, probes[k].sphere, BasicInterval<T>{});
}

// A triangle test's answers: for each ray, how many of its triangles it hit, and the first hit.
template <class T>
struct TriangleAnswer {
    int hits = 0;
    int first = -1;  // the first triangle hit
    T t = 0;         // and its t
};

template <class T, class Test>
void run(const TriangleProbes<T>& probes, const Test& test, std::vector<TriangleAnswer<T>>& answers)
{
    answers.assign(probes.rays.size(), TriangleAnswer<T>{});
    const auto one = [&](size_t k, int f) {
        if (const std::optional<TriangleHit<T>> hit = test(probes.rays[k], probes.triangles[f], BasicInterval<T>{})) {
            if (answers[k].hits++ == 0) {
                answers[k].first = f;
                answers[k].t = hit->t;
            }
        }
    };
    for (size_t k = 0; k < probes.rays.size(); ++k) {
        if (probes.targets[k].empty())
            for (int f = 0; f < static_cast<int>(probes.triangles.size()); ++f)
                one(k, f);
        else
            for (const int f : probes.targets[k])
                one(k, f);
    }
}

// How many intersection tests a run makes.
template <class T>
std::uint64_t tests_in(const std::vector<SphereProbe<T>>& probes)
{
    return probes.size();
}

template <class T>
std::uint64_t tests_in(const TriangleProbes<T>& probes)
{
    std::uint64_t n = 0;
    for (const std::vector<int>& t : probes.targets)
        n += t.empty() ? probes.triangles.size() : t.size();
    return n;
}

struct Score {
    std::uint64_t answers = 0;
    std::uint64_t wrong = 0;       // a hit where the exact answer misses, or the other way round
    double max_rel_t_error = 0.0;  // over the answers that hit where the exact answer does too
    size_t first_wrong = npos;     // which probe, for a test's failure message
    size_t worst_t = npos;
    static constexpr size_t npos = static_cast<size_t>(-1);

    double wrong_fraction() const { return answers ? static_cast<double>(wrong) / static_cast<double>(answers) : 0.0; }

    void add(size_t probe, bool right, double rel_t_error)
    {
        ++answers;
        if (!right) {
            if (wrong++ == 0)
                first_wrong = probe;
        } else if (rel_t_error > max_rel_t_error) {
            max_rel_t_error = rel_t_error;
            worst_t = probe;
        }
    }
};

inline double rel_error(long double actual, long double exact)
{
    return static_cast<double>(exact != 0 ? std::abs((actual - exact) / exact) : std::abs(actual));
}

template <class T>
Score score(const std::vector<SphereProbe<T>>& probes, const std::vector<std::optional<T>>& answers)
{
    Score s;
    for (size_t k = 0; k < probes.size(); ++k) {
        const exact::Answer want = exact::sphere(probes[k].ray, probes[k].sphere, BasicInterval<T>{});
        const bool right = answers[k].has_value() == want.hit;
        s.add(k, right, right && want.hit ? rel_error(*answers[k], want.t) : 0.0);
    }
    return s;
}

template <class T>
Score score(const TriangleProbes<T>& probes, const std::vector<TriangleAnswer<T>>& answers)
{
    using Expect = typename TriangleProbes<T>::Expect;
    Score s;
    for (size_t k = 0; k < probes.rays.size(); ++k) {
        const TriangleAnswer<T>& got = answers[k];
        const bool should_hit = probes.expect == Expect::exact
                                    ? exact::triangle(probes.rays[k], probes.triangles[probes.targets[k][0]],
                                                      BasicInterval<T>{}).hit
                                    : probes.expect == Expect::some_hit;
        const bool right = (got.hits > 0) == should_hit;
        double t_error = 0.0;
        if (right && got.hits > 0)  // against where the ray meets the plane of the triangle it hit
            t_error = rel_error(got.t, exact::triangle(probes.rays[k], probes.triangles[got.first], BasicInterval<T>{}).t);
        s.add(k, right, t_error);
    }
    return s;
}

}  // namespace rt::extremes
