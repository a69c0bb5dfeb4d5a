// Legal scenes that once broke a structure: objects all at one point, each around all the others,
// scenes flat in a plane through the origin, tiny and single-object scenes. Every structure of
// chapters 07-10 must build them within its budgets and answer every seeded ray as brute force does
// (object and t), without testing many times more objects than brute force; the hashed grid must
// say when its build holds many times the dense grid's memory (memory_weighed.hpp).
#include "04_shadow_feelers/self_intersection.hpp"
#include "10_hierarchies/figure.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/structures/memory_weighed.hpp"

#include <functional>
#include <string>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

// Every structure of the registry (programs/structures.hpp) but brute force, the reference.
Structures structures() { return beside_brute_force(ch10::structures()); }

// How agreement::compare builds `s` at a density.
agreement::BuildFn built_at(const Structure& s)
{
    return [s](const Objects& objects, float lambda) { return s.make(objects, at_density(lambda)); };
}

// Why 1 GB: the most a structure may take for a scene below 100k objects, whatever its shape.
constexpr std::size_t max_bytes = std::size_t{1} << 30;

// Why 3 times: a structure may cost more than brute force's one test per object per ray where it
// cannot sort objects apart (a walk through several cells of one list), but not many times more;
// and below grid_pays_floor tests a ray (chapter 07's grid.hpp) a few objects cost nothing either way.
constexpr double max_tests_over_brute = 3.0;

// The structure `s` built over `objects`; the hashed grid's word on its memory checked
// (memory_weighed.hpp) from the notices said while it was built.
std::unique_ptr<Accelerator> built_saying(const Structure& s, const Objects& objects, float lambda)
{
    std::unique_ptr<Accelerator> built;
    std::vector<std::string> said;
    {
        const NoticeCapture capture;
        built = s.make(objects, at_density(lambda));
        said = capture.lines();
    }
    if (const auto* hashed = dynamic_cast<const HashedGrid*>(built.get()))
        memory_weighed::check(objects, *hashed, said);
    return built;
}

struct Work {
    std::uint64_t tests = 0;
};

// The most a structure may test on a scene's rays: `times` brute force's tests, and `per_ray` more
// on each ray.
struct WorkBound {
    double times = max_tests_over_brute;
    double per_ray = grid_pays_floor;
};

using WorkBounds = std::function<WorkBound(const std::string& structure)>;

// The tests brute force and `accel` make for the same seeded rays (agreement::compare's rays): the
// same answers, and no more tests than `most` allows the structure.
void check(const std::string& scene_name, const LitScene& scene, const NffView& view, int rays,
           const WorkBounds& most = [](const std::string&) { return WorkBound{}; })
{
    const Objects objects = objects_of(scene, lit_tests);
    // Brute force's work on the rays, from the counters: compare() asks it twice a query, as the
    // reference and here as the structure. The rays do not depend on the density, so once serves
    // every structure.
    reset_counters();
    agreement::Disagreement brute_d;
    agreement::compare({"brute force", [](const Objects&, float) { return std::make_unique<BruteForce>(); }}, scene, view,
                       1.0f, rays, 7, brute_d);
    const double brute_tests = static_cast<double>(counted(total_counts(), Counter::intersection_tests)) / 2.0;
    for (const Structure& s : structures()) {
        INFO(scene_name << " (" << objects.size() << " objects) through " << s.name << " (" << s.what << ")");
        reset_counters();
        agreement::Disagreement d;
        agreement::compare({s.name, built_at(s)}, scene, view, s.default_lambda, rays, 7, d);
        const std::uint64_t with_structure = counted(total_counts(), Counter::intersection_tests);
        // compare() asks brute force too: the structure's own tests are the difference.
        const double structure_tests = static_cast<double>(with_structure) - brute_tests;
        INFO(d.wrong << " of " << d.rays << " rays answered differently from brute force; the first: " << d.first);
        CHECK(d.wrong == 0);
        const WorkBound bound = most(s.name);
        INFO("tests: brute force " << brute_tests << ", the structure " << structure_tests << " (at most " << bound.times
                                   << " times brute force's, and " << bound.per_ray << " a ray more)");
        CHECK(structure_tests <= bound.times * brute_tests + bound.per_ray * d.rays);
        const std::unique_ptr<Accelerator> built = built_saying(s, objects, s.default_lambda);
        INFO("bytes: " << built->bytes());
        CHECK(built->bytes() <= max_bytes);
    }
}

LitScene with_material()
{
    LitScene scene;
    scene.add_material({});
    return scene;
}

// A point drawn uniformly from `low` to `low + size` on each axis, x, y and z in that order. One draw
// a statement: a constructor's arguments are evaluated in an order each compiler picks.
vec3 drawn(Rng& rng, const vec3& low, const vec3& size)
{
    const float x = size.x * rng.next_float() + low.x;
    const float y = size.y * rng.next_float() + low.y;
    const float z = size.z * rng.next_float() + low.z;
    return vec3(x, y, z);
}

NffView looking_at(const point3& at, float distance)
{
    NffView view;
    view.at = at;
    view.from = at + vec3(0.3f, 0.4f, 1.0f) * distance;
    return view;
}

// One ray, in two ranges, through every structure built at `lambda`: the same object at the same
// t as brute force, and the same any-hit answer.
void check_ray(const LitScene& scene, const Ray& ray, float lambda)
{
    const Objects objects = objects_of(scene, lit_tests);
    for (const Interval range : {Interval{0.0f, infinity}, Interval{1e-4f, 10.0f}}) {
        ObjectHit want;
        const bool want_found = brute_force().closest(ray, range, objects, want);
        const bool want_any = brute_force().any(ray, range, objects);
        for (const Structure& s : structures()) {
            const std::unique_ptr<Accelerator> built = built_saying(s, objects, lambda);
            ObjectHit got;
            const bool got_found = built->closest(ray, range, objects, got);
            INFO(s.name << ": " << show(ray) << ", t in (" << range.min << ", " << range.max
                 << "): brute force finds " << agreement::answer(want_found, want) << ", the structure "
                 << agreement::answer(got_found, got));
            CHECK(got_found == want_found);
            CHECK(got.object == want.object);
            CHECK(got.t == want.t);
            CHECK(built->any(ray, range, objects) == want_any);
        }
    }
}

}  // namespace

TEST_CASE("objects all at one point, or each around all the others, are no harder than brute force", "[structures]")
{
    // 33,000 identical unit spheres at one point: once 4.4e9 references through 32-bit counts.
    LitScene same = with_material();
    for (int k = 0; k < 33000; ++k)
        same.add_sphere({point3(0.5f, -0.25f, 1.0f), 1.0f}, 0);
    check("33,000 identical unit spheres", same, looking_at(point3(0.5f, -0.25f, 1.0f), 6.0f), 60);

    // 20,000 spheres of radius 100 within 1 of the origin: each holds all the others' centres.
    LitScene nested = with_material();
    Rng rng(3, 1);
    for (int k = 0; k < 20000; ++k) {
        const float x = 2 * rng.next_float() - 1, y = 2 * rng.next_float() - 1, z = 2 * rng.next_float() - 1;
        nested.add_sphere({point3(x, y, z), 100.0f}, 0);
    }
    check("20,000 spheres of radius 100 within 1 of the origin", nested, looking_at(point3(0.0f), 400.0f), 60);
}

TEST_CASE("a scene flat in a coordinate plane through 0 builds a flat grid and answers as brute force", "[structures]")
{
    LitScene one = with_material();
    one.add_triangle({point3(0, 0, 0), point3(1, 0, 0), point3(1, 1, 0)}, 0);
    check("one triangle at z = 0", one, looking_at(point3(0.6f, 0.4f, 0.0f), 3.0f), 400);

    // 50,000 triangles tiling a square at z = 0.
    LitScene floor = with_material();
    const int n = 158;  // 2 n^2 > 50,000
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const point3 a(i, j, 0), b(i + 1, j, 0), c(i + 1, j + 1, 0), d(i, j + 1, 0);
            floor.add_triangle({a, b, c}, 0);
            floor.add_triangle({a, c, d}, 0);
        }
    check("50,000 triangles at z = 0", floor, looking_at(point3(n / 2.0f, n / 2.0f, 0.0f), n / 2.0f), 80);
    const Objects objects = objects_of(floor, lit_tests);
    GridStats stats;
    build_grid(objects, margins_of(objects), ch07::default_lambda, &stats);
    INFO("the grid over 50,000 triangles at z = 0: " << stats.resolution.x << " x " << stats.resolution.y << " x "
                                                      << stats.resolution.z);
    CHECK(stats.resolution.z == 1);
    CHECK(stats.resolution.x > 100);
}

TEST_CASE("a single object, anywhere and of any size, builds in every structure", "[structures]")
{
    for (const float size : {1e-15f, 1e-6f, 1.0f, 1e6f}) {
        for (const point3 at : {point3(0.0f), point3(-1.0f, -1.0f, 0.0f), point3(1e3f, -2e3f, 5e2f)}) {
            LitScene one = with_material();
            one.add_triangle({at, at + vec3(size, 0, 0), at + vec3(0, size, 0)}, 0);
            std::ostringstream name;
            name << "one triangle " << size << " across at " << show(at);
            check(name.str(), one, looking_at(at + vec3(0.3f * size, 0.3f * size, 0.0f), 3.0f * size), 200);
        }
    }
    LitScene tiny = with_material();
    for (int k = 0; k < 10; ++k)
        tiny.add_sphere({point3(k * 1e-16f, 0.0f, 0.0f), 1e-16f}, 0);
    check("ten spheres 1e-15 across in all", tiny, looking_at(point3(5e-16f, 0.0f, 0.0f), 1e-14f), 200);
}

TEST_CASE("a ray leaving a triangle never finds it again, however large the triangle or far from the origin", "[structures]")
{
    // Once: a floor 2e5 across under a camera 11 above it speckled with its own shadow (a feeler 1.5e-5
    // above it "hit" it at t = 0.002), and the BVH disagreed with brute force there. Each triangle
    // alone in its scene; hit points where camera rays meet it, feelers leaving on both sides in every
    // direction (grazing ones included), from the robust offset (EXERCISE 04.3).
    struct Placed {
        std::string name;
        Triangle tri;
        point3 eye;
    };
    const std::vector<Placed> triangles = {
        {"a triangle 2e5 across at y = 0 through the origin", {{-1e5f, 0, -1e5f}, {0, 0, 1e5f}, {1e5f, 0, -1e5f}}, {0, 11, 0.5f}},
        {"a tilted triangle 2e5 across spanning the origin", {{-1e5f, -3e3f, -1e5f}, {0, 1e3f, 1e5f}, {1e5f, 200, -1e5f}}, {0, 200, 0.5f}},
        {"a tilted triangle 2e5 across, 1e5 from the origin", {{0, -3e3f, 0}, {1e5f, 1e3f, 2e5f}, {2e5f, 200, 0}}, {1e5f, 200, 1e5f}},
        {"a triangle 2e7 across at z = 0", {{-1e7f, -1e7f, 0}, {1e7f, -1e7f, 0}, {0, 1e7f, 0}}, {3, 2, 40}},
        {"a triangle 1 across at 1e6 from the origin", {{1e6f, 1e6f, 1e6f}, {1e6f + 1, 1e6f, 1e6f}, {1e6f, 1e6f + 1, 1e6f + 0.5f}}, {1e6f + 0.3f, 1e6f + 0.3f, 1e6f + 3}},
    };
    for (const Placed& placed : triangles) {
        LitScene scene = with_material();
        scene.add_triangle(placed.tri, 0);
        const vec3 n = face_normal(placed.tri);
        const point3 centroid = (placed.tri.a + placed.tri.b + placed.tri.c) / 3.0f;
        Rng rng(31, 0);
        int hits = 0, rehits = 0;
        std::string first;
        for (int k = 0; k < 4000; ++k) {
            // A camera ray toward a random point of the triangle.
            float beta = rng.next_float();
            float gamma = rng.next_float();
            if (beta + gamma > 1.0f) {
                beta = 1.0f - beta;
                gamma = 1.0f - gamma;
            }
            const point3 target = placed.tri.a + beta * (placed.tri.b - placed.tri.a) + gamma * (placed.tri.c - placed.tri.a);
            const point3 eye = k % 2 ? placed.eye : centroid + (centroid - placed.eye);  // each side in turn
            const Ray ray{eye, glm::normalize(target - eye)};
            const std::optional<Hit> hit = closest_hit(ray, scene, Interval{0.0f, infinity});
            if (!hit)
                continue;
            ++hits;
            const vec3 away = self_intersection::random_in_hemisphere(rng, k % 4 < 2 ? n : -n);
            const Ray feeler{offset_ray_origin(hit->p, hit->n, away), away};
            const std::optional<Hit> again = closest_hit(feeler, scene, Interval{0.0f, infinity});
            if (again && rehits++ == 0)
                first = "the feeler from " + show(hit->p) + " along " + show(away) + " met it again at t = " +
                        std::to_string(again->t);
        }
        INFO(placed.name << ": " << rehits << " of " << hits << " feelers found their own triangle again; " << first);
        CHECK(hits > 3000);
        CHECK(rehits == 0);
    }
}

TEST_CASE("a floor 2e7 across is drawn from 1 to 1e6 above it, by brute force and every structure", "[structures]")
{
    // Once: seen from 1 above, chapter 04 on drew nothing of it. The float test's bound on t grows
    // with the corners' distance from the eye (1e7), and refused every hit nearer than it, however
    // certainly in front; now double decides there (shape_tests.hpp).
    const Triangle tri{{-1e7f, 0, 1e7f}, {1e7f, 0, 1e7f}, {0, 0, -1e7f}};
    LitScene floor = with_material();
    floor.add_triangle(tri, 0);
    for (const float height : {1.0f, 3.0f, 100.0f, 1e4f, 1e6f}) {
        const point3 eye(0, height, 0);
        Rng rng(43, 1);
        int misses = 0, far_off = 0;
        std::string first;
        for (int k = 0; k < 2000; ++k) {
            // A point of the floor inside it (its edges pass 4.4e6 from the origin), 0.5 to 3e6 from
            // the eye's foot: the nearest rays look steeply down, the farthest graze it.
            const float r = std::exp2(-1.0f + 22.5f * rng.next_float());
            const float angle = 6.2831853f * rng.next_float();
            const point3 target(r * std::cos(angle), 0, r * std::sin(angle));
            const vec3 to = target - eye;
            const Ray ray{eye, glm::normalize(to)};
            const std::optional<Hit> hit = closest_hit(ray, floor, Interval{0.0f, infinity});
            // Where the float test decides, its t is as good as its own bound on t's rounding, which
            // grows with the corners' 1e7 (0.1 at 600 from an eye 100 up); where double decides, better.
            const float distance = glm::length(to);
            const float within = std::max(1e-4f * distance, watertight_t_error(ray, tri));
            const bool wrong = !hit || std::abs(hit->t - distance) > within;
            misses += hit ? 0 : 1;
            far_off += hit && wrong ? 1 : 0;
            if (wrong && first.empty())
                first = show(ray) + " toward " + show(target) + ": " + (hit ? "t = " + std::to_string(hit->t) : "no hit") +
                        ", the floor is " + std::to_string(distance) + " away";
        }
        INFO("the eye " << height << " above the floor: " << misses << " of 2000 rays toward it missed it, " << far_off
                        << " hit it far from where it is; the first: " << first);
        CHECK(misses == 0);
        CHECK(far_off == 0);
        NffView view;
        view.from = eye;
        view.at = point3(0, 0, 100.0f * height);
        check("a floor 2e7 across seen from " + std::to_string(height) + " above", floor, view, 200);
    }
}

TEST_CASE("a floor 2e5 across under a camera 11 above it answers as brute force through every structure", "[structures]")
{
    LitScene floor = with_material();
    floor.add_triangle({{-1e5f, 0, -1e5f}, {0, 0, 1e5f}, {1e5f, 0, -1e5f}}, 0);
    NffView view;
    view.from = point3(0, 11, 0.5f);
    view.at = point3(30, 0, 30);
    check("a floor 2e5 across", floor, view, 400);
}

TEST_CASE("300 spheres 100 across, 1e7 from the origin, build cells no finer than their rounding", "[structures]")
{
    // Once: the hashed grid listed each sphere 41,000 times (15.5 s, 149 MB), its margin of 16 float
    // steps (9.5 units) spread over cells 2 units wide.
    LitScene far = with_material();
    Rng rng(9, 0);
    for (int k = 0; k < 300; ++k)
        far.add_sphere({point3(1e7f) + drawn(rng, vec3(-50), vec3(100)), 2.0f}, 0);
    check("300 spheres 1e7 from the origin", far, looking_at(point3(1e7f), 250.0f), 200);
    const Objects objects = objects_of(far, lit_tests);
    const HashedGridStats stats = HashedGrid(objects, ch09::default_hashed_lambda).stats();
    INFO("the hashed grid: " << stats.resolution.x << " x " << stats.resolution.y << " x " << stats.resolution.z
                             << " cells, " << stats.references << " references");
    CHECK(stats.references <= 100 * 300);
}

TEST_CASE("long thin slivers, one huge triangle over thousands of tiny ones, and a shrinking spiral answer as brute force", "[structures]")
{
    // 5,000 slivers 0.01 wide and up to 14 long, every way across a box 16 wide: each crosses many cells.
    LitScene slivers = with_material();
    Rng rng(12, 0);
    // A point in the box [-h, h]^3, one draw a statement (argument order is each compiler's choice).
    const auto draw = [&rng](float h) {
        vec3 v;
        for (int i = 0; i < 3; ++i)
            v[i] = 2 * h * rng.next_float() - h;
        return v;
    };
    for (int k = 0; k < 5000; ++k) {
        const point3 a = draw(8.0f);
        const vec3 along = draw(8.0f);
        slivers.add_triangle({a, a + along, a + along + vec3(0.01f, 0, 0.005f)}, 0);
    }
    check("5,000 long thin slivers", slivers, looking_at(point3(0.0f), 30.0f), 60);

    // One triangle 2,000 across over 5,000 triangles 0.05 across: the huge one is in every cell.
    LitScene huge = with_material();
    huge.add_triangle({{-1000, 1, -1000}, {0, 1, 1000}, {1000, 1, -1000}}, 0);
    for (int k = 0; k < 5000; ++k) {
        point3 a = draw(10.0f);
        a.y = 2.9f * rng.next_float() - 2;
        huge.add_triangle({a, a + vec3(0.05f, 0, 0), a + vec3(0, 0.05f, 0.02f)}, 0);
    }
    check("a huge triangle over 5,000 tiny ones", huge, looking_at(point3(0.0f), 30.0f), 60);

    // After SPD's shells: 5,761 spheres along a spiral, each 0.999 the size of the one before, the
    // first large enough to hold many of the others: the hashed grid once listed each 19,090 times.
    LitScene spiral = with_material();
    float r = 1.0f;
    for (int k = 0; k < 5761; ++k, r *= 0.999f) {
        const float angle = 0.05f * static_cast<float>(k);
        spiral.add_sphere({point3(r * 3 * std::cos(angle), r * 3 * std::sin(angle), 0.002f * static_cast<float>(k)), r}, 0);
    }
    check("a spiral of 5,761 shrinking spheres", spiral, looking_at(point3(0.0f, 0.0f, 5.0f), 20.0f), 60);
}

TEST_CASE("a sphere of subnormal radius beside zero-area triangles is found through every structure", "[structures]")
{
    // accel_fuzz's finding: the scene's box is 1e-6 long and 1.4e-42 across, the sphere at its end.
    LitScene scene = with_material();
    scene.add_sphere({{0, 0, 0}, 7.17464814e-43f}, 0);
    for (int copy = 0; copy < 2; ++copy)
        scene.add_triangle({{1.83347781e-12f, 0, 0}, {1.00000182e-06f, 0, 0}, {0, 0, 0}}, 0);
    check_ray(scene, Ray{{9.9375f, 0, 0}, {-1, 0, 0}}, 5.5f);
}

TEST_CASE("copies of a sliver whose float t lies beyond its bound's reach tie to the lower number in every structure", "[structures]")
{
    // accel_fuzz's findings. Each sliver's float t is further from the truth than its float step, and
    // within the bound on it, so the answer is double's t: asked again for a tie in a range that ends
    // one step past that answer, the float t alone fell outside it, and the BVH kept the copy it met
    // first, not the lower-numbered one brute force keeps.
    LitScene fan = with_material();
    fan.add_sphere({{0, 0, 0}, 3.0f}, 0);
    for (int copy = 0; copy < 3; ++copy)
        fan.add_triangle({{0, 0, 2}, {9.99999997e-07f, 0, 2}, {0, -3, 0}}, 0);
    check_ray(fan, Ray{{0, 0, 0}, {0, -0.832050323f, 0.554700196f}}, 0.25f);

    LitScene corner = with_material();
    const Triangle slivers[] = {{{15.9375f, 15.9375f, 15.9375f}, {15.937501f, 15.9375f, 15.9375f}, {0, 0, -1}},
                                {{1.5f, 0, 0}, {1.50000095f, 0, 0}, {0, -1.5f, -2}},
                                {{2, 0, 0}, {2.00000095f, 0, 0}, {0, 0, 0}}};
    for (const Triangle& t : slivers)
        for (int copy = 0; copy < 2; ++copy)
            corner.add_triangle(t, 0);
    check_ray(corner, Ray{{3.99999999e-06f, 3.99999999e-06f, 3.99999999e-06f}, {0.577350259f, 0.577350259f, 0.577350259f}}, 0.25f);
}

namespace {

// `count` spheres of radius 2e-4 drawn (seeded) in a box 0.01 across about the origin.
void add_cluster(LitScene& scene, int count, std::uint64_t seed)
{
    Rng rng(seed, 0);
    for (int k = 0; k < count; ++k)
        scene.add_sphere({point3(drawn(rng, vec3(-0.005f), vec3(0.01f))), 2e-4f}, 0);
}

// The cluster seen from 0.03 away, filling the view.
NffView near_the_cluster()
{
    NffView view;
    view.from = point3(0.01f, 0.012f, 0.03f);
    view.at = point3(0.0f);
    return view;
}

}  // namespace

TEST_CASE("a dense cluster beside one far sphere costs every structure no more than brute force, the BVH under a tenth", "[structures]")
{
    // 100,000 spheres of radius 2e-4 in a box 0.01 across, and one sphere 1000 away. A margin of
    // 1e-5 of the scene's extent would be 0.01, wider than the cluster: no cell or node could sort
    // it apart, and every structure would test about twice brute force's objects.
    LitScene cluster = with_material();
    add_cluster(cluster, 100000, 43);
    cluster.add_sphere({{1000, 0, 0}, 1}, 0);
    NffView view;
    view.from = point3(0.004f, 0.006f, 0.025f);
    view.at = point3(0.0f);
    check("a cluster 0.01 across beside a sphere at x = 1000", cluster, view, 40, [](const std::string& structure) {
        return WorkBound{structure == "bvh" || structure == "bvh4" ? 0.1 : 1.0, 0.0};
    });
}

TEST_CASE("one triangle 2e5 across over 5,000 triangles 1e-3 across costs the hierarchy of grids no more than brute force", "[structures]")
{
    // A margin of 1e-5 of the scene's extent would be 2 here, against triangles 1e-3 across: the
    // hierarchy of grids would list each small triangle in many cells and test 4.4 times brute force's
    // objects.
    LitScene huge = with_material();
    huge.add_triangle({{-1e5f, -1, -1e5f}, {0, -1, 1e5f}, {1e5f, -1, -1e5f}}, 0);
    Rng rng(44, 0);
    for (int k = 0; k < 5000; ++k) {
        const vec3 p = drawn(rng, vec3(-1, -0.9f, -1), vec3(2, 1.9f, 2));
        const float x = p.x, y = p.y, z = p.z;
        huge.add_triangle({{x, y, z}, {x + 1e-3f, y, z}, {x, y + 1e-3f, z + 4e-4f}}, 0);
    }
    NffView view;
    view.from = point3(0, 2.5f, 3);
    view.at = point3(0, -0.5f, 0);
    check("a triangle 2e5 across over 5,000 triangles 1e-3 across", huge, view, 200, [](const std::string& structure) {
        return structure == "hgrid" ? WorkBound{1.0, 0.0} : WorkBound{};
    });
}

TEST_CASE("a cluster 0.01 across beside one sphere 1e4 away (ratio 1e6) costs every structure no more than brute force", "[structures]")
{
    // The margins once took the scene's box for where rays start: 2^-20 of 1e4 is 0.0095, about the
    // cluster's width, and the hashed grid and the hierarchy of grids tested 1.2 and 1.06 times brute
    // force's objects on these rays.
    LitScene cluster = with_material();
    add_cluster(cluster, 20000, 45);
    cluster.add_sphere({{1e4f, 0, 0}, 0.01f}, 0);
    check("a cluster 0.01 across beside a sphere at x = 1e4", cluster, near_the_cluster(), 40,
          [](const std::string&) { return WorkBound{1.0, 0.0}; });
}

TEST_CASE("a cluster 0.01 across in the plane of a triangle 1e6 across costs every structure no more than brute force", "[structures]")
{
    // The triangle's 5e5 once set every margin (0.48, fifty times the cluster): the hierarchy of grids
    // tested 1.3 times brute force's objects on these rays.
    LitScene plane = with_material();
    plane.add_triangle({{-5e5f, 0, 5e5f}, {5e5f, 0, 5e5f}, {0, 0, -5e5f}}, 0);
    add_cluster(plane, 20000, 46);
    check("a cluster 0.01 across in the plane of a triangle 1e6 across", plane, near_the_cluster(), 40,
          [](const std::string&) { return WorkBound{1.0, 0.0}; });
}

TEST_CASE("one flat triangle 2e6 across over 20,000 triangles 5e-3 across costs every structure but the two grids without mailboxes no more than brute force", "[structures]")
{
    // The hierarchy of grids once tested 4.3 times brute force's objects here (the margins of the
    // small triangles were 2^-20 of 1e6, about 0.95). The grid and the hashed grid are held to
    // the default bound only: their cells are 7,000 wide, a boundary runs through the cluster at x = 0
    // and z = 0, and 07.2 and 07.4 place boundaries in float, so each object within 4 roundings of 2e6
    // (0.48) of one is listed on both sides, and a ray crossing both tests it twice. On these rays,
    // spread wide, many miss the cluster and they stay under brute force's count; on rays that all
    // cross it they test about twice its objects, and the hierarchy of grids (whose root grid is the
    // plain one) more than once. The grid with mailboxes tests each once (chapter 08's lesson);
    // sorting the cluster apart would take 07.2 and 07.4 in double (chapter 07's lesson, "The grid's
    // own cells round too").
    LitScene huge = with_material();
    huge.add_triangle({{-1e6f, 0, 1e6f}, {1e6f, 0, 1e6f}, {0, 0, -1e6f}}, 0);
    for (int i = 0; i < 142; ++i)
        for (int j = 0; j < 142; ++j) {
            const float x = 0.007f * (i - 71), z = 0.007f * (j - 71), y = 0.002f * (1 + (i + j) % 3);
            huge.add_triangle({{x, y, z}, {x + 0.005f, y, z}, {x, y + 3e-4f, z + 0.005f}}, 0);
        }
    NffView view;
    view.from = point3(0.3f, 0.5f, 0.8f);
    view.at = point3(0.0f);
    check("a triangle 2e6 across over 20,164 triangles 5e-3 across", huge, view, 40, [](const std::string& structure) {
        return structure == "grid" || structure == "hashed" ? WorkBound{} : WorkBound{1.0, 0.0};
    });
}

TEST_CASE("an eye 5e5 times the scene's size away: every structure answers as brute force does", "[structures]")
{
    // 4,000 triangles in a box 1 across seen from 5e5 away: a hit's t there rounds by some 0.03 of
    // the scene, past any margin a cell could afford; the structures once differed on 15 of 4096 such
    // rays (the margins assumed rays start near the scene's box).
    LitScene far = with_material();
    Rng rng(47, 0);
    for (int k = 0; k < 4000; ++k) {
        const vec3 c = drawn(rng, vec3(-0.5f), vec3(1.0f));
        const vec3 a = drawn(rng, vec3(-0.03f), vec3(0.06f)), b = drawn(rng, vec3(-0.03f), vec3(0.06f)),
                   d = drawn(rng, vec3(-0.03f), vec3(0.06f));
        far.add_triangle({c + a, c + b, c + d}, 0);
    }
    NffView view;
    view.from = point3(3e5f, 2e5f, 4e5f);
    view.at = point3(0.0f);
    // The rays from the eye: agreement::compare spreads them 0.6 radians about the view, so most miss
    // the scene; these are aimed at its box.
    const Objects objects = objects_of(far, lit_tests);
    // The rays and brute force's answers, once for every structure.
    struct Asked {
        Ray ray;
        bool found = false;
        ObjectHit hit;
    };
    std::vector<Asked> asked(4000);
    Rng aim(48, 0);
    for (Asked& a : asked) {
        const vec3 target = drawn(aim, vec3(-0.5f), vec3(1.0f));
        a.ray = {view.from, glm::normalize(target - view.from)};
        a.found = brute_force().closest(a.ray, {0.0f, infinity}, objects, a.hit);
    }
    for (const Structure& s : structures()) {
        const std::unique_ptr<Accelerator> built = s.make(objects, at_density(s.default_lambda));
        int wrong = 0;
        std::string first;
        for (const Asked& a : asked) {
            const Ray& ray = a.ray;
            const ObjectHit& want = a.hit;
            const bool want_found = a.found;
            ObjectHit got;
            const bool got_found = built->closest(ray, {0.0f, infinity}, objects, got);
            if (want_found != got_found || (want_found && (want.object != got.object || want.t != got.t)))
                if (wrong++ == 0)
                    first = show(ray) + ": brute force " + (want_found ? show(want) : "no hit") + ", the structure " +
                            (got_found ? show(got) : "no hit");
        }
        INFO(s.name << ": " << wrong << " of 4000 rays from the far eye answered unlike brute force; the first: "
                    << first);
        CHECK(wrong == 0);
    }
}
