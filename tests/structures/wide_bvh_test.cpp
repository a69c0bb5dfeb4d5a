// The 4-wide BVH (chapter 10's wide_bvh.hpp, given): the binary tree collapsed four children to a
// node must keep every leaf once and every box as it was, and answer every ray as brute force does
// (object and t, bit for bit). Compiled twice: with the SSE test of the four boxes where the
// processor has it, and with RT_WIDE_SCALAR, the plain C++ one other processors run.
#include "10_hierarchies/figure.hpp"
#include "10_hierarchies/wide_bvh.hpp"
#include "tests/ch07/agreement.hpp"
#include "tests/ch10/closed_sphere.hpp"
#include "tests/structures/sah_splits.hpp"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <utility>

using namespace rt;
using namespace rt::grader;
using namespace rt::grader::agreement;

namespace {

const char* const lanes = lanes_kind;

Build wide(int leaf_size)
{
    return {"the 4-wide BVH (leaves of " + std::to_string(leaf_size) + ", " + lanes + ")",
            [leaf_size](const Objects& objects, float) {
                BvhSettings s;
                s.leaf_size = leaf_size;
                return std::make_unique<WideBvhAccel>(objects, s);
            }};
}

Bounds child_box(const WideNode& w, int i)
{
    Bounds b;
    for (int a = 0; a < 3; ++a) {
        b.min[a] = w.min[a][i];
        b.max[a] = w.max[a][i];
    }
    return b;
}

bool same_box(const Bounds& a, const Bounds& b) { return a.min == b.min && a.max == b.max; }

}  // namespace

TEST_CASE("the 4-wide BVH answers every ray as brute force does, on the kit's scenes and generated ones", "[structures]")
{
    INFO("the four boxes tested with " << lanes);
    for (const auto& entry : std::filesystem::directory_iterator(RT_NFF_SCENES_DIR))
        if (entry.path().extension() == ".nff") {
            check_scene(wide(4), read_nff(entry.path().string()), 400);
            check_scene(wide(1), read_nff(entry.path().string()), 200);
        }
    check_scene(wide(4), generated_scene(write_stadium, 2, "stadium 2"), 600);
    check_scene(wide(4), generated_scene(write_sticks, 1, "sticks 1"), 600);
    check_scene(wide(1), generated_scene(write_tree, 3, "tree 3"), 400);
}

TEST_CASE("the 4-wide BVH answers as brute force does on ties, a huge floor and far from the origin", "[structures]")
{
    INFO("the four boxes tested with " << lanes);
    check_hard_cases(wide(4));
    check_hard_cases(wide(1));
}

TEST_CASE("the four boxes of a wide node are entered exactly when the slab test enters each one", "[structures]")
{
    // Boxes and rays on a coarse lattice, so that origins lie on faces (with d_i = 0: a NaN slab, or
    // +0 and -0), rays graze edges and corners, and boxes are flat or empty; ranges that end on a
    // face. Every box must be entered, at the same t, exactly when slab_interval enters it; an empty
    // slot (min +infinity, max -infinity) never is.
    Rng rng(77, 2);
    const auto lattice = [&] { return static_cast<float>(static_cast<int>(rng.next_float() * 7.0f) - 3); };
    int checked = 0, entered = 0;
    for (int k = 0; k < 50000; ++k) {
        WideNode node{};
        Bounds boxes[4];
        for (int i = 0; i < 4; ++i) {
            if (rng.next_float() < 0.1f) {
                boxes[i] = Bounds{};  // an empty slot
            } else {
                const point3 p(lattice(), lattice(), lattice()), q(lattice(), lattice(), lattice());
                boxes[i] = {glm::min(p, q), glm::max(p, q)};
            }
            for (int a = 0; a < 3; ++a) {
                node.min[a][i] = boxes[i].min[a];
                node.max[a][i] = boxes[i].max[a];
            }
        }
        vec3 d(lattice(), lattice(), lattice());
        if (rng.next_float() < 0.2f)
            d[static_cast<int>(rng.next_float() * 3.0f)] = rng.next_float() < 0.5f ? 0.0f : -0.0f;
        if (d == vec3(0.0f))
            continue;
        const Ray ray{point3(lattice(), lattice(), lattice()), glm::normalize(d)};
        const Interval reach{rng.next_float() < 0.5f ? 0.0f : 1.0f, rng.next_float() < 0.5f ? infinity : 2.0f};
        const RaySlabs slabs(ray);
        float t0[4];
        const unsigned got = enter_boxes(node, slabs, reach, t0);
        for (int i = 0; i < 4; ++i) {
            const std::optional<Interval> want = slab_interval(boxes[i], slabs, reach);
            const bool in = got >> i & 1u;
            INFO(show(ray) << ", t in (" << reach.min << ", " << reach.max << "), box " << show(boxes[i].min) << " to "
                 << show(boxes[i].max) << " (" << lanes << "): the slab test says "
                 << (want ? "entered at t = " + std::to_string(want->min) : std::string("missed")) << ", the wide test "
                 << (in ? "entered at t = " + std::to_string(t0[i]) : std::string("missed")));
            REQUIRE(in == want.has_value());
            if (in)
                REQUIRE(t0[i] == want->min);
            ++checked;
            entered += in;
        }
    }
    INFO(entered << " of " << checked << " boxes entered");
    CHECK(entered > checked / 10);
    CHECK(entered < checked);
}

TEST_CASE("the SAH build bins on these lanes as the lesson bins, one box at a time", "[structures]")
{
    // The binary tree the wide one collapses, binned four floats at a time on this program's lanes
    // (SSE, or the plain C++ of RT_WIDE_SCALAR): each split as tests/structures/sah_splits.hpp
    // re-derives it.
    INFO("lanes: " << lanes_kind);
    const LitScene scene = lit_scene(generated_scene(write_mountain, 5, "mountain 5"));
    CHECK(check_sah_splits(objects_of(scene, lit_tests), BvhSettings{}, "mountain 5") > 10);
}

TEST_CASE("collapsed four wide, the tree keeps each leaf of the binary tree once, with its box", "[structures]")
{
    // The tree (spheres, cones, and a floor of triangles: leaves of each kind) and a mountain
    // (triangles and four spheres: many leaves in blocks).
    const LitScene tree = lit_scene(generated_scene(write_tree, 4, "tree 4"));
    const LitScene mountain = lit_scene(generated_scene(write_mountain, 4, "mountain 4"));
    struct Case {
        const char* name;
        const LitScene& scene;
        int leaf_size;
    };
    for (const Case& c : {Case{"tree 4", tree, 1}, Case{"tree 4", tree, 4}, Case{"mountain 4", mountain, 4}}) {
        const int leaf_size = c.leaf_size;
        INFO(c.name);
        const Objects objects = objects_of(c.scene, lit_tests);
        BvhSettings s;
        s.leaf_size = leaf_size;
        const BvhAccel binary(objects, s);
        const WideBvhAccel wide(objects, s);
        // The binary leaves by their first object number: each must appear once, with the same
        // objects and box. (A wide leaf of triangles names its objects in its blocks, another kind
        // in object_index.)
        std::map<std::uint32_t, std::pair<std::vector<std::uint32_t>, Bounds>> leaves;
        const auto& order = binary.bvh().object_index;
        for (const BvhNode& n : binary.bvh().nodes)
            if (n.count > 0)
                leaves[order[n.first]] = {{order.begin() + n.first, order.begin() + n.first + n.count}, n.bounds()};
        const WideBvh& w = wide.tree();
        const auto objects_of_leaf = [&w](const WideNode& node, int i) {
            std::vector<std::uint32_t> list;
            for (std::uint32_t j = 0; j < node.count[i]; ++j)
                list.push_back(node.in_blocks >> i & 1u ? static_cast<std::uint32_t>(w.blocks[node.first[i] + j / 4].object[j % 4])
                                                        : w.object_index[node.first[i] + j]);
            return list;
        };
        int block_leaves = 0;
        std::vector<int> referenced(w.nodes.size(), 0);
        std::map<std::uint32_t, int> seen;
        int empty_slots = 0;
        for (std::size_t k = 0; k < w.nodes.size(); ++k)
            for (int i = 0; i < 4; ++i) {
                const WideNode& node = w.nodes[k];
                const Bounds box = child_box(node, i);
                INFO("leaves of " << leaf_size << ": wide node " << k << ", child " << i);
                if (!(node.occupied >> i & 1u)) {
                    CHECK(box.empty());
                    ++empty_slots;
                    continue;
                }
                if (node.count[i] == 0) {
                    REQUIRE(node.first[i] < w.nodes.size());
                    ++referenced[node.first[i]];
                    // An inner child's box is the box around its own children's: no looser (a
                    // ray would enter it for nothing), no tighter (it would miss what they hold).
                    Bounds around;
                    const WideNode& child = w.nodes[node.first[i]];
                    for (int j = 0; j < 4; ++j)
                        if (child.occupied >> j & 1u)
                            around.grow(child_box(child, j));
                    INFO(show(box) << " around children within " << show(around));
                    CHECK(same_box(box, around));
                    continue;
                }
                const std::vector<std::uint32_t> held = objects_of_leaf(node, i);
                block_leaves += node.in_blocks >> i & 1u;
                const auto leaf = leaves.find(held[0]);
                INFO("leaves of " << leaf_size << ": a wide leaf of " << node.count[i] << " objects from object " << held[0]
                                  << (node.in_blocks >> i & 1u ? ", in blocks" : ""));
                REQUIRE(leaf != leaves.end());
                CHECK(leaf->second.first == held);
                CHECK(same_box(leaf->second.second, box));
                ++seen[held[0]];
            }
        INFO("leaves of " << leaf_size << ": " << leaves.size() << " binary leaves, " << seen.size() << " found in "
             << w.nodes.size() << " wide nodes (" << empty_slots << " empty slots)");
        CHECK(seen.size() == leaves.size());
        CHECK(block_leaves > 0);  // the tree's floor, at least
        for (const auto& [first, times] : seen)
            CHECK(times == 1);
        CHECK(referenced[0] == 0);  // the root
        for (std::size_t k = 1; k < referenced.size(); ++k)
            CHECK(referenced[k] == 1);
        // A binary tree of n leaves has n - 1 inner nodes; each wide node takes the place of one to
        // three of them: a collapse that opened none would make n - 1. A wide node holds four
        // children unless every child it could open is a leaf.
        CHECK(w.nodes.size() <= leaves.size() - 1);
        for (std::size_t k = 0; k < w.nodes.size(); ++k) {
            const WideNode& node = w.nodes[k];
            if (node.occupied == 0xfu)
                continue;
            for (int i = 0; i < 4; ++i) {
                INFO("leaves of " << leaf_size << ": wide node " << k << " holds fewer than four children, yet its child " << i
                                  << " is an inner node");
                CHECK(!(node.occupied >> i & 1u && node.count[i] == 0));
            }
        }
    }
}

TEST_CASE("the 4-wide BVH tests no more objects than the binary tree it was made from, give or take", "[structures]")
{
    // Both trees share their leaves and cull by the same best hit; the wide one meets its leaves in
    // a slightly different order, so its count may differ a little, but not by much: a traversal
    // that never culled, or went far to near, would test several times as many.
    const LitScene scene = lit_scene(generated_scene(write_stadium, 2, "stadium 2"));
    const Objects objects = objects_of(scene, lit_tests);
    const BvhAccel binary(objects);
    const WideBvhAccel wide(objects);
    const auto tests_over = [&](const Accelerator& tree) {
        Rng rng(9, 4);
        reset_counters();
        for (int k = 0; k < 4000; ++k) {
            const point3 from(60 * rng.next_float() - 30, 20 * rng.next_float(), 60 * rng.next_float() - 30);
            const vec3 d = glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1));
            ObjectHit hit;
            tree.closest({from, d}, {0.0f, infinity}, objects, hit);
        }
        return total_count(Counter::intersection_tests);
    };
    const std::uint64_t by_binary = tests_over(binary), by_wide = tests_over(wide);
    INFO("4000 seeded closest-hit queries on the stadium (depth 2): the binary tree made " << by_binary
         << " object tests, the wide tree " << by_wide << " (" << lanes << ")");
    CHECK(by_binary > 0);
    CHECK(by_wide <= by_binary + by_binary / 4);
}

TEST_CASE("rays leaving a floor answer as brute force does through the 4-wide BVH, which passes the floor's block over", "[structures]")
{
    // The pyramid stands on a floor at y = 0. Rays leave the pyramid's faces and the floor from
    // chapter 04's robust origin, into either side, and from points on the floor's plane, just above
    // and just below it; every answer must be brute force's, and a ray leaving the floor must test
    // fewer triangles than the floor's block holds on top of the rest (WideQuery::leaves_plane).
    const LitScene scene = lit_scene(generated_scene(write_pyramid, 2, "pyramid 2"));
    const Objects objects = objects_of(scene, lit_tests);
    const WideBvhAccel wide(objects);
    int flat_blocks = 0;
    for (const FourTriangles& g : wide.tree().blocks)
        flat_blocks += g.flat_axis == 1 && g.flat_at == 0.0f;
    INFO("blocks on the floor's plane: " << flat_blocks << " (" << lanes << ")");
    REQUIRE(flat_blocks > 0);
    Rng rng(54, 14);
    const auto u = [&] { return 2.0f * rng.next_float() - 1.0f; };
    int rays = 0, wrong = 0, leaving_floor = 0;
    std::uint64_t floor_tests = 0;
    for (int k = 0; k < 3000; ++k) {
        // A point on a surface: a brute-force hit of a ray from above, or a point of the floor.
        const Ray down{point3(3.0f * u(), 2.0f, 3.0f * u()), glm::normalize(vec3(0.3f * u(), -1.0f, 0.3f * u()))};
        ObjectHit h;
        if (!brute_force().closest(down, {0.0f, infinity}, objects, h))
            continue;
        const point3 p = down.origin + h.t * down.dir;
        const vec3 n = glm::normalize(face_normal(objects.triangles[objects.ref(h.object).index]));
        const vec3 d = glm::normalize(vec3(u(), u(), u()));
        point3 origins[4] = {offset_ray_origin(p, n, d), point3(p.x, 0.0f, p.z), point3(p.x, 1e-7f, p.z), point3(p.x, -1e-7f, p.z)};
        for (const point3& o : origins) {
            const Ray ray{o, d};
            ObjectHit want, got;
            reset_counters();
            const bool got_found = wide.closest(ray, {0.0f, infinity}, objects, got);
            const std::uint64_t tests = total_count(Counter::intersection_tests);
            const bool want_found = brute_force().closest(ray, {0.0f, infinity}, objects, want);
            const bool same = want_found == got_found && (!want_found || (want.object == got.object && want.t == got.t)) &&
                              brute_force().any(ray, {0.0f, infinity}, objects) == wide.any(ray, {0.0f, infinity}, objects);
            ++rays;
            if (!same && wrong++ == 0)
                FAIL_CHECK(show(ray) << ": brute force " << agreement::answer(want_found, want) << ", the wide tree "
                                     << agreement::answer(got_found, got) << " (" << lanes << ")");
            if (o.y > 0.0f && d.y > 0.0f && std::abs(o.y) < 1e-3f) {
                ++leaving_floor;
                floor_tests += tests;
            }
        }
    }
    INFO(rays << " rays, " << wrong << " answered differently; " << leaving_floor << " rays leaving the floor tested "
              << floor_tests << " triangles (" << lanes << ")");
    CHECK(wrong == 0);
    REQUIRE(leaving_floor > 100);
    CHECK(floor_tests < 2u * static_cast<std::uint64_t>(leaving_floor));
}

#if RT_WIDE_SSE
TEST_CASE("with tiny floats flushed to 0, the 4-wide BVH still enters no empty slot", "[structures]")
{
    // Flush-to-zero and denormals-are-zero (what -ffast-math sets): a direction of huge components
    // has 1 / d flushed to 0, every slab of an empty slot is (infinity - o) * 0 = NaN, and the
    // empty box would be entered; the node's mask keeps the ray out.
    LitScene scene;
    scene.add_material({});
    for (int k = 0; k < 3; ++k)
        scene.add_sphere({point3(3.0f * static_cast<float>(k), 0, 0), 1.0f}, 0);
    const Objects objects = objects_of(scene, lit_tests);
    BvhSettings s;
    s.leaf_size = 1;
    const WideBvhAccel tree(objects, s);
    REQUIRE(tree.tree().nodes.size() == 1);
    REQUIRE(tree.tree().nodes[0].occupied != 0xfu);  // three spheres: an empty slot
    const unsigned csr = _mm_getcsr();
    _mm_setcsr(csr | 0x8040u);
    const Ray huge{{0, 0, 5}, {3e38f, 3e38f, -3e38f}};
    ObjectHit hit, want;
    const bool any = tree.any(huge, {0.0f, infinity}, objects);
    const bool closest = tree.closest(huge, {0.0f, infinity}, objects, hit);
    const bool want_any = brute_force().any(huge, {0.0f, infinity}, objects);
    const bool want_closest = brute_force().closest(huge, {0.0f, infinity}, objects, want);
    _mm_setcsr(csr);
    INFO("a ray of direction (3e38, 3e38, -3e38) with FTZ and DAZ set: the wide tree says any-hit " << any
         << ", closest " << answer(closest, hit) << "; brute force " << want_any << ", " << answer(want_closest, want));
    CHECK(any == want_any);
    CHECK(closest == want_closest);
    CHECK((!closest || (hit.object == want.object && hit.t == want.t)));
}
#endif

TEST_CASE("a 4-wide BVH of one leaf or of nothing answers as brute force does", "[structures]")
{
    LitScene one;
    one.add_material({});
    one.add_sphere({point3(0, 0, -3), 1.0f}, 0);
    const Objects objects = objects_of(one, lit_tests);
    const WideBvhAccel tree(objects);
    REQUIRE(tree.tree().nodes.size() == 1);
    ObjectHit hit;
    CHECK(tree.closest({{0, 0, 0}, {0, 0, -1}}, {0.0f, infinity}, objects, hit));
    CHECK(hit.object == 0);
    CHECK(std::abs(hit.t - 2.0f) < 1e-6f);
    CHECK(!tree.closest({{0, 0, 0}, {0, 0, 1}}, {0.0f, infinity}, objects, hit));
    CHECK(!tree.any({{0, std::nanf(""), 0}, {0, 0, -1}}, {0.0f, infinity}, objects));

    const LitScene nothing;
    const Objects none = objects_of(nothing, lit_tests);
    const WideBvhAccel empty(none);
    CHECK(empty.tree().nodes.empty());
    CHECK(!empty.closest({{0, 0, 0}, {0, 0, -1}}, {0.0f, infinity}, none, hit));
    CHECK(!empty.any({{0, 0, 0}, {0, 0, -1}}, {0.0f, infinity}, none));
}

TEST_CASE("watertight through the 4-wide BVH: 10^5 rays from inside a closed sphere of triangles far from the origin all hit it", "[structures]")
{
    const Escapes e = escapes_from_closed_sphere<WideBvhAccel>(100000, 4321);
    INFO("10^5 rays from within 200 of the centre of " << e.scene << ", " << lanes << ": " << e.escaped
         << " escaped; the first: " << e.first);
    CHECK(e.escaped == 0);
}

TEST_CASE("the 4-wide BVH answers as brute force does with the watertight test unbounded, with one-sided triangles, and with Moller-Trumbore", "[structures]")
{
    // Its leaves of triangles are tested four at once for the watertight tests only (with and
    // without chapter 04's bound on t), and must keep the classic rules' one-sided triangles; the
    // other tests go one by one. Each way, every seeded ray as brute force answers it.
    const LitScene scene = lit_scene(generated_scene(write_stadium, 2, "stadium 2"));
    std::vector<bool> front_only(scene.triangles.size());
    Rng pick(3, 3);
    for (size_t i = 0; i < front_only.size(); ++i)
        front_only[i] = pick.next_float() < 0.5f;
    struct Way {
        const char* name;
        ShapeTests tests;
        const std::vector<bool>* one_sided;
    };
    const Way ways[] = {{"watertight", {SphereTest::precise, TriangleTest::watertight}, nullptr},
                        {"watertight, half the triangles one-sided", {SphereTest::precise, TriangleTest::watertight}, &front_only},
                        {"watertight bounded, half one-sided", lit_tests, &front_only},
                        {"Moller-Trumbore", {SphereTest::precise, TriangleTest::moller_trumbore}, nullptr}};
    for (const Way& way : ways) {
        Objects objects = objects_of(scene, way.tests);
        objects.one_sided = way.one_sided;
        const WideBvhAccel tree(objects);
        Rng rng(17, 5);
        int hits = 0;
        for (int k = 0; k < 3000; ++k) {
            const point3 from(60 * rng.next_float() - 30, 20 * rng.next_float(), 60 * rng.next_float() - 30);
            const vec3 d = glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1));
            const Ray ray{from, d};
            ObjectHit got, want;
            const bool found = tree.closest(ray, {0.0f, infinity}, objects, got);
            const bool wanted = brute_force().closest(ray, {0.0f, infinity}, objects, want);
            INFO(way.name << " (" << lanes << "): " << show(ray) << ", the wide tree " << answer(found, got)
                          << ", brute force " << answer(wanted, want));
            REQUIRE(found == wanted);
            REQUIRE(tree.any(ray, {0.0f, infinity}, objects) == wanted);
            if (found) {
                REQUIRE(got.object == want.object);
                REQUIRE(got.t == want.t);
                REQUIRE(got.beta == want.beta);
                REQUIRE(got.gamma == want.gamma);
                ++hits;
            }
        }
        INFO(way.name << ": " << hits << " of 3000 rays hit");
        CHECK(hits > 1000);
    }
}

namespace {

// Four triangles about a ray, each within `size` of a point `along` the ray's length ahead (or
// behind), corners drawn at random: most are hit along the ray's line, some missed; and the ray from
// a point within `size` of `center`, in a random direction.
struct LaneCase {
    Ray ray;
    Triangle tri[4];
    FourTriangles g{};
};

LaneCase lane_case(Rng& rng, float center, float size, float along)
{
    const auto u = [&] { return 2.0f * rng.next_float() - 1.0f; };
    LaneCase c;
    c.ray = Ray{point3(center + size * u(), center + size * u(), center + size * u()), glm::normalize(vec3(u(), u(), u()) + vec3(0.0f, 0.0f, 0.1f))};
    for (int i = 0; i < 4; ++i) {
        const point3 p = c.ray.origin + along * u() * c.ray.dir;
        const point3 corner[3] = {p + size * vec3(u(), u(), u()), p + size * vec3(u(), u(), u()), p + size * vec3(u(), u(), u())};
        c.tri[i] = {corner[0], corner[1], corner[2]};
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a)
                c.g.p[k][a][i] = corner[k][a];
        c.g.object[i] = i;
    }
    return c;
}

}  // namespace

TEST_CASE("four at once, chapter 04's bound on t is at least each triangle's own, at every scale a float holds", "[structures]")
{
    // The wide tree passes over a lane by this bound (lane_bounds.hpp): below the one-by-one bound,
    // it could pass over a lane whose answer, worked out one by one, wins.
    Rng rng(54, 11);
    long long asked = 0, known = 0, asked_ordinary = 0, known_ordinary = 0;
    for (int e = -60; e <= 60; e += 3)
        for (float spread : {1e-3f, 1.0f, 1e3f})
            for (int k = 0; k < 60; ++k) {
                const float scale = std::ldexp(1.0f, e);
                const LaneCase c = lane_case(rng, scale * (rng.next_float() < 0.5f ? 0.0f : 1e3f), scale, scale * spread);
                const FourBounds b = four_t_error_bounds(c.g, ray_frame(c.ray));
                for (int i = 0; i < 4; ++i) {
                    ++asked;
                    const bool ordinary = e >= -20 && e <= 20;
                    asked_ordinary += ordinary;
                    if (!lane_in(b.known, i))
                        continue;
                    ++known;
                    known_ordinary += ordinary;
                    const float one = watertight_t_error(c.ray, c.tri[i]);
                    INFO("scale 2^" << e << ", lane " << i << ": four at once " << b.upper[i] << ", one by one " << one
                                    << " (" << lanes << ")");
                    REQUIRE(b.upper[i] >= one);
                }
            }
    INFO(known << " of " << asked << " lanes known; " << known_ordinary << " of " << asked_ordinary
               << " at scales 2^-20 to 2^20");
    CHECK(known_ordinary > asked_ordinary * 9 / 10);
}

TEST_CASE("a lane the bound refuses is refused one by one, one it puts inside a range is hit there, and one it answers gets bounded_answer's t", "[structures]")
{
    // LaneAnswer's decisions against the bounded test's own answer (bounded_answer), for ranges
    // that end a few bounds either side of the float t: where the plane's t in double or double's
    // own test moves the answer off the float t, the decisions must still hold. And where the
    // four-lane bounds decide bounded_answer's own steps, the wide tree's answer is its, bit for bit.
    Rng rng(54, 12);
    long long refused = 0, inside = 0, lanes_hit = 0, answered_by_lanes = 0;
    const float ends[] = {-10.0f, -3.5f, -3.0f, -2.0f, -1.0f, 0.0f, 1.0f, 2.0f, 3.0f, 3.5f, 10.0f};
    for (int e = -30; e <= 30; e += 5)
        for (int k = 0; k < 200; ++k) {
            const float scale = std::ldexp(1.0f, e);
            const LaneCase c = lane_case(rng, scale * (rng.next_float() < 0.5f ? 0.0f : 1e4f), scale, scale * (k % 3 == 0 ? 1e-3f : 2.0f));
            const FourBounds b = four_t_error_bounds(c.g, ray_frame(c.ray));
            for (int i = 0; i < 4; ++i) {
                const auto hit = hit_triangle_watertight(c.ray, c.tri[i], Interval{-infinity, infinity});
                if (!hit || !lane_in(b.known, i))
                    continue;
                ++lanes_hit;
                TriangleHit<float> answer;
                const bool answered = bounded_answer(c.ray, c.tri[i], *hit, answer);
                const LaneAnswer lane{hit->t, b.upper[i], b.lower[i]};
                if (lane.beyond() && (lane.coarse() || lane.fine())) {
                    ++answered_by_lanes;
                    TriangleHit<float> by_lanes;
                    answer_beyond_bound(c.ray, c.tri[i], *hit, lane.coarse(), by_lanes);
                    INFO("scale 2^" << e << ": float t " << hit->t << ", bounds " << b.lower[i] << " to " << b.upper[i]
                                    << ": four lanes answer t " << by_lanes.t << ", bounded_answer "
                                    << (answered ? answer.t : NAN));
                    REQUIRE(answered);
                    REQUIRE(std::memcmp(&by_lanes, &answer, sizeof answer) == 0);
                }
                for (float lo : ends)
                    for (float hi : ends) {
                        if (!(lo < hi))
                            continue;
                        const Interval range{hit->t + lo * b.upper[i], hit->t + hi * b.upper[i]};
                        const bool in = answered && range.surrounds(answer.t);
                        INFO("scale 2^" << e << ": float t " << hit->t << ", bound " << b.upper[i] << ", answer "
                                        << (answered ? answer.t : NAN) << ", range (" << range.min << ", "
                                        << range.max << ")");
                        if (lane.refused_by(range)) {
                            ++refused;
                            REQUIRE_FALSE(in);
                        }
                        if (lane.certainly_in(range)) {
                            ++inside;
                            REQUIRE(in);
                        }
                    }
            }
        }
    INFO(lanes_hit << " lanes hit; decided: " << refused << " refused, " << inside << " inside; "
                   << answered_by_lanes << " answered from the four-lane bounds");
    CHECK(refused > lanes_hit);
    CHECK(inside > lanes_hit / 4);
    CHECK(answered_by_lanes > lanes_hit / 3);
}

TEST_CASE("Float4's arithmetic and compares are float's, lane by lane, special values included", "[structures]")
{
    // 10.6 is 02.5 written with Float4 in place of float: it answers as 02.5 does only if each
    // operation is the float operation in each lane, rounding, infinities, NaN and -0 included.
    Rng rng(41, 9);
    const float special[] = {0.0f, -0.0f, infinity, -infinity, std::nanf(""), 1e-45f, -1e-40f, 3e38f, 1.0f, -1.0f};
    const auto value = [&] {
        const float r = rng.next_float();
        if (r < 0.3f)
            return special[static_cast<int>(rng.next_float() * 10.0f) % 10];
        return (rng.next_float() - 0.5f) * std::ldexp(1.0f, static_cast<int>(rng.next_float() * 60.0f) - 30);
    };
    const auto same = [](float x, float y) { return (std::isnan(x) && std::isnan(y)) || std::memcmp(&x, &y, sizeof x) == 0; };
    for (int k = 0; k < 20000; ++k) {
        float a[4], b[4], got[4];
        for (int i = 0; i < 4; ++i)
            a[i] = value(), b[i] = value();
        const Float4 A = Float4::load(a), B = Float4::load(b);
        const struct {
            const char* op;
            Float4 lanes;
            float (*one)(float, float);
        } ops[] = {{"+", A + B, [](float x, float y) { return x + y; }},
                   {"-", A - B, [](float x, float y) { return x - y; }},
                   {"*", A * B, [](float x, float y) { return x * y; }},
                   {"/", A / B, [](float x, float y) { return x / y; }}};
        for (const auto& o : ops) {
            o.lanes.store(got);
            for (int i = 0; i < 4; ++i) {
                INFO(a[i] << ' ' << o.op << ' ' << b[i] << " (" << lanes << "): Float4 gives " << got[i] << ", float "
                          << o.one(a[i], b[i]));
                REQUIRE(same(got[i], o.one(a[i], b[i])));
            }
        }
        abs(A).store(got);
        for (int i = 0; i < 4; ++i) {
            INFO("|" << a[i] << "| (" << lanes << "): Float4 gives " << got[i]);
            REQUIRE(same(got[i], std::fabs(a[i])));
        }
        const unsigned lt = bits(A < B), gt = bits(A > B), eq = bits(A == B), ne = bits(A != B);
        const unsigned mixed = bits(~(A < B) & ((A == B) | (A != B)));
        for (int i = 0; i < 4; ++i) {
            INFO(a[i] << " against " << b[i] << " (" << lanes << ")");
            REQUIRE(bool(lt >> i & 1u) == (a[i] < b[i]));
            REQUIRE(bool(gt >> i & 1u) == (a[i] > b[i]));
            REQUIRE(bool(eq >> i & 1u) == (a[i] == b[i]));
            REQUIRE(bool(ne >> i & 1u) == (a[i] != b[i]));
            REQUIRE(bool(mixed >> i & 1u) == (!(a[i] < b[i]) && (a[i] == b[i] || a[i] != b[i])));
        }
    }
}
