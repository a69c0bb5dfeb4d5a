// EXERCISE 02.5: the watertight test of Woop, Benthin and Wald (JCGT 2013).
#include "tests/ch02/triangle_cases.hpp"

#include <iomanip>
#include <sstream>
#include <type_traits>

using namespace rt;
using namespace rt::grader;

RT_TRIANGLE_BEHAVIOURS(hit_triangle_watertight, "02.5")

STABILITY_TEST("hit_triangle_watertight: triangles without area are never hit, pbrt-v4's BadCase included", "02.5", 1)
{
    triangles::degenerate(&hit_triangle_watertight<float>, {0, 1, 2, 3, 4, 5, 6});
}

namespace {

// Float and double, against the exact answers: no ray aimed at a shared vertex or edge slips
// between the triangles, and the hit's t is as exact as the float inputs allow.
template <class T>
void check_watertight(const std::string& what, const extremes::TriangleProbes<T>& probes)
{
    std::vector<extremes::TriangleAnswer<T>> answers;
    extremes::run(probes, &hit_triangle_watertight<T>, answers);
    const extremes::Score score = extremes::score(probes, answers);
    INFO(describe(what + (std::is_same_v<T, float> ? " (float)" : " (double)"), probes, answers, score));
    CHECK(score.wrong == 0);
    CHECK(score.max_rel_t_error <= (std::is_same_v<T, float> ? 1e-6 : 1e-14));
}

template <class T>
void check_watertight_mesh()
{
    const IndexedMesh mesh = extremes::jittered_icosphere(15);
    check_watertight("rays aimed at the shared vertices of a jittered icosphere, each tested against the faces around it",
                     extremes::vertex_aimed<T>(mesh, 40, 15));
    check_watertight("rays aimed at the shared edges of a jittered icosphere, each tested against the two faces along it",
                     extremes::edge_aimed<T>(mesh, 20, 15));
    check_watertight("rays from the centre of a closed mesh at (148376, 1234, -223423) aimed at its vertices and edges",
                     extremes::inside_far_mesh<T>(4000, 15));
}

}  // namespace

STABILITY_TEST("hit_triangle_watertight: rays at a mesh's shared vertices and edges never slip through, float and double", "02.5", 3)
{
    check_watertight_mesh<float>();
    check_watertight_mesh<double>();
}

namespace {

// The lesson's steps 1-5 as the hints' walk-through writes them, in float: what the test must
// compute, bit for bit, when an edge function comes out exactly 0 in float. Then all three are
// computed again from the same sheared coordinates in double, where the products of floats are
// exact, and rounded to float; det, t, beta and gamma follow from those three floats.
struct WatertightSteps {
    bool fell_back = false;                  // some edge function was exactly 0 in float
    float U = 0, V = 0, W = 0;               // the edge functions the sign test reads
    std::optional<TriangleHit<float>> hit;  // what the test returns
};

// The mistakes these steps can make on purpose, for counting where a case tells them apart:
// recomputing the three in double even when none is 0 in float (the answer float's own products and
// difference would not give); taking the earlier axis on a tie of v's largest components.
struct StepsMistake {
    bool always_double = false;
    bool earlier_axis_on_tie = false;
};

WatertightSteps watertight_steps(const Ray& ray, const Triangle& tri, Interval range, StepsMistake mistake = {})
{
    WatertightSteps s;
    const vec3 n = glm::cross(tri.b - tri.a, tri.c - tri.a);
    if (n.x == 0 && n.y == 0 && n.z == 0)
        return s;
    const vec3 ad = glm::abs(ray.dir);
    // The largest |v[k]|; on a tie the later axis (the lesson's step 2).
    const int kz = mistake.earlier_axis_on_tie ? (ad.x >= ad.y ? (ad.x >= ad.z ? 0 : 2) : (ad.y >= ad.z ? 1 : 2))
                                               : (ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2));
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (ray.dir[kz] < 0)
        std::swap(kx, ky);
    const float Sx = ray.dir[kx] / ray.dir[kz], Sy = ray.dir[ky] / ray.dir[kz], Sz = 1.0f / ray.dir[kz];
    const vec3 A = tri.a - ray.origin, B = tri.b - ray.origin, C = tri.c - ray.origin;
    const float Ax = A[kx] - Sx * A[kz], Ay = A[ky] - Sy * A[kz];
    const float Bx = B[kx] - Sx * B[kz], By = B[ky] - Sy * B[kz];
    const float Cx = C[kx] - Sx * C[kz], Cy = C[ky] - Sy * C[kz];
    s.U = cross_2d(Cx, Cy, Bx, By);
    s.V = cross_2d(Ax, Ay, Cx, Cy);
    s.W = cross_2d(Bx, By, Ax, Ay);
    if (s.U == 0 || s.V == 0 || s.W == 0 || mistake.always_double) {
        s.fell_back = s.U == 0 || s.V == 0 || s.W == 0;
        s.U = static_cast<float>(cross_2d<double>(Cx, Cy, Bx, By));
        s.V = static_cast<float>(cross_2d<double>(Ax, Ay, Cx, Cy));
        s.W = static_cast<float>(cross_2d<double>(Bx, By, Ax, Ay));
    }
    if ((s.U < 0 || s.V < 0 || s.W < 0) && (s.U > 0 || s.V > 0 || s.W > 0))
        return s;
    const float det = s.U + s.V + s.W;
    if (det == 0)
        return s;
    const float t = (s.U * (Sz * A[kz]) + s.V * (Sz * B[kz]) + s.W * (Sz * C[kz])) / det;
    if (!range.surrounds(t))
        return s;
    s.hit = TriangleHit<float>{t, s.V / det, s.W / det};
    return s;
}

// The same float to the last bit (+0 and -0 count as one: no caller can tell them apart).
bool same_bits(float a, float b) { return a == b; }

std::string bits(const std::optional<TriangleHit<float>>& hit)
{
    if (!hit)
        return "no hit";
    std::ostringstream s;
    s << std::hexfloat << "t = " << hit->t << ", beta = " << hit->beta << ", gamma = " << hit->gamma;
    return s.str();
}

// What differs first between an answer and the lesson's steps, in words: the likeliest cause, and
// whether double applies on this ray (an edge function exactly 0 in float) or not. The formula is the
// lesson's, not the message's.
std::string first_difference(const std::optional<TriangleHit<float>>& got, const WatertightSteps& want)
{
    if (got.has_value() != want.hit.has_value()) {
        if (want.fell_back)
            return got ? "a hit where the edge functions, taken again in double (one is 0 in float here), put the ray outside"
                       : "no hit where the edge functions, taken again in double (one is 0 in float here), put the ray inside";
        return got ? "a hit where the float edge functions differ in sign (none is 0 here, so double does not apply)"
                   : "no hit where the float edge functions agree in sign (none is 0 here, so double does not apply)";
    }
    if (!got)
        return "";
    if (!same_bits(got->beta, want.hit->beta) || !same_bits(got->gamma, want.hit->gamma))
        return want.fell_back ? "beta or gamma differs in its last bits: an edge function is 0 in float here, so all "
                                "three are taken again in double and rounded to float before det is summed"
                              : "beta or gamma differs in its last bits: no edge function is 0 here, so the float ones "
                                "stand; is each divided by det (a product with 1 / det rounds differently)?";
    if (!same_bits(got->t, want.hit->t))
        return "t differs in its last bits: is it summed in the lesson's order and divided by det (a product with "
               "1 / det rounds differently)?";
    return "";
}

bool same_answer(const std::optional<TriangleHit<float>>& a, const std::optional<TriangleHit<float>>& b)
{
    if (a.has_value() != b.has_value())
        return false;
    return !a || (same_bits(a->t, b->t) && same_bits(a->beta, b->beta) && same_bits(a->gamma, b->gamma));
}

// Calls check(ray, tri, want) for each ray aimed exactly at a shared vertex or edge of a jittered
// icosphere and each face around what it is aimed at, want being the lesson's steps for the two.
template <class Check>
void for_each_vertex_and_edge_test(Check check)
{
    const IndexedMesh mesh = extremes::jittered_icosphere(15);
    for (const extremes::TriangleProbes<float>& probes :
         {extremes::vertex_aimed<float>(mesh, 40, 15), extremes::edge_aimed<float>(mesh, 20, 15)}) {
        for (size_t k = 0; k < probes.rays.size(); ++k)
            for (const int f : probes.targets[k])
                check(probes.rays[k], probes.triangles[f], watertight_steps(probes.rays[k], probes.triangles[f], Interval{}));
    }
}

}  // namespace

GRADED_TEST("hit_triangle_watertight: an edge function that rounds to 0 in float is decided in double: all three recomputed and rounded to float, t, beta and gamma to the bit", "02.5", 2)
{
    // A ray along -z from the origin, so the sheared corners are just (y, x) of each corner. Edge
    // b-c passes 2^-46 beside the origin: its two products, (1 + 2^-23)^2 and 1 + 2^-22, round to
    // the same float and U is 0 in float, -2^-46 in double. With corner a on one side of the edge
    // the ray is inside (U, V, W all negative); on the other it is outside (V, W positive), which
    // only the double recomputation can tell. The products of V and W are not exact in float, so
    // recomputing them in double (as the lesson says: all three) changes their last bits.
    const float e = 0x1p-23f;
    const point3 b{1 + e, 1 + 2 * e, -4}, c{-1, -(1 + e), -5};
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    for (const float side : {1.0f, -1.0f}) {
        const Triangle tri{{side * -0x1.14cfa2p-1f, side * 0x1.203376p-1f, -3}, b, c};
        const WatertightSteps want = watertight_steps(ray, tri, Interval{});
        const std::optional<TriangleHit<float>> got = hit_triangle_watertight<float>(ray, tri, Interval{});
        INFO(triangles::query(ray, tri, Interval{}) << std::hexfloat << ": the edge functions in float have U = 0; recomputed in double "
             << "and rounded to float, U = " << want.U << ", V = " << want.V << ", W = " << want.W << ", so the ray is "
             << (want.hit ? "inside" : "outside") << ".\n  got " << bits(got) << "\n  expected " << bits(want.hit)
             << "\n  " << first_difference(got, want));
        REQUIRE(want.fell_back);
        CHECK(same_answer(got, want.hit));
    }
}

STABILITY_TEST("hit_triangle_watertight: wherever an edge function is 0 in float (rays at a mesh's vertices and edges), the answer is the double recomputation's, to the bit", "02.5", 2)
{
    // Rays aimed exactly at shared vertices and edges often make an edge function 0 in float (about
    // 17000 of 58000 tests here): each such answer must be what the lesson's steps give.
    int fell_back = 0;
    for_each_vertex_and_edge_test([&](const Ray& ray, const Triangle& tri, const WatertightSteps& want) {
        if (!want.fell_back)
            return;
        ++fell_back;
        const std::optional<TriangleHit<float>> got = hit_triangle_watertight<float>(ray, tri, Interval{});
        INFO(triangles::query(ray, tri, Interval{}) << std::hexfloat << ": an edge function is 0 in float; recomputed in "
             << "double and rounded to float, U = " << want.U << ", V = " << want.V << ", W = " << want.W
             << ".\n  got " << bits(got) << "\n  expected " << bits(want.hit) << "\n  " << first_difference(got, want));
        REQUIRE(same_answer(got, want.hit));
    });
    INFO(fell_back << " tests took the double recomputation");
    CHECK(fell_back >= 1000);
}

STABILITY_TEST("hit_triangle_watertight: where no edge function is 0 in float, U, V and W stay float's own (no double recomputation): t, beta and gamma to the bit", "02.5", 1)
{
    // The double recomputation is for an edge function that float rounded to 0, and only then: the
    // others are cross_2d in float, two rounded products and their rounded difference, which the
    // four-lane test of 10.6 repeats to the bit. Recomputed in double and rounded back, a product
    // difference that cancels keeps digits float's products lost, and t, beta or gamma move by a
    // few last bits (here in hundreds of the tests below).
    int in_float = 0, telling = 0;
    for_each_vertex_and_edge_test([&](const Ray& ray, const Triangle& tri, const WatertightSteps& want) {
        if (want.fell_back)
            return;
        ++in_float;
        if (!same_answer(watertight_steps(ray, tri, Interval{}, {true, false}).hit, want.hit))
            ++telling;
        const std::optional<TriangleHit<float>> got = hit_triangle_watertight<float>(ray, tri, Interval{});
        INFO(triangles::query(ray, tri, Interval{}) << std::hexfloat << ": no edge function is 0 in float, "
             << "so U = " << want.U << ", V = " << want.V << ", W = " << want.W << " as cross_2d gives them in float."
             << "\n  got " << bits(got) << "\n  expected " << bits(want.hit) << "\n  "
             << (same_answer(got, watertight_steps(ray, tri, Interval{}, {true, false}).hit) && !same_answer(got, want.hit)
                     ? "that is the answer of U, V and W recomputed in double: only an edge function that is 0 "
                       "in float is recomputed"
                     : first_difference(got, want)));
        REQUIRE(same_answer(got, want.hit));
    });
    INFO(in_float << " tests stayed in float; in " << telling << " of them a double recomputation changes the answer");
    CHECK(telling >= 100);
}

GRADED_TEST("hit_triangle_watertight: on a tie of v's largest components the frame's z is the later axis (z before y, y before x): t, beta and gamma to the bit", "02.5", 2)
{
    // Directions whose two or three largest |v[k]| are equal: the lesson's step 2 takes the later
    // axis. Another frame is as watertight, but shears the corners otherwise, and t, beta and gamma
    // round to other bits (10.6's four lanes repeat this frame to the bit).
    const IndexedMesh mesh = extremes::jittered_icosphere(15);
    int tests = 0, telling = 0;
    for (const vec3& v : {vec3(1, 1, 0.5f), vec3(-1, 1, -0.25f), vec3(0.75f, -2, 2), vec3(2, 0.5f, -2), vec3(1, 1, 1),
                          vec3(-3, -3, -3), vec3(-1, 1, 0)}) {
        const float f = 1e-3f;
        for (std::size_t k = 0; k < mesh.faces.size(); k += 7) {
            const Triangle tri{mesh.vertices[mesh.faces[k][0]], mesh.vertices[mesh.faces[k][1]], mesh.vertices[mesh.faces[k][2]]};
            // From 4 lengths of v before a point inside the face, off its centre.
            const point3 aim = (0.5f + f) * tri.a + 0.3f * tri.b + (0.2f - f) * tri.c;
            const Ray ray{aim - 4.0f * v, v};
            const WatertightSteps want = watertight_steps(ray, tri, Interval{});
            ++tests;
            if (!same_answer(watertight_steps(ray, tri, Interval{}, {false, true}).hit, want.hit))
                ++telling;
            const std::optional<TriangleHit<float>> got = hit_triangle_watertight<float>(ray, tri, Interval{});
            INFO(triangles::query(ray, tri, Interval{}) << ": v's largest components tie; the frame's z is the later "
                 << "axis of the tie.\n  got " << bits(got) << "\n  expected " << bits(want.hit) << "\n  "
                 << (same_answer(got, watertight_steps(ray, tri, Interval{}, {false, true}).hit)
                         ? "that is the answer of the earlier axis's frame: on a tie take the later axis (z before y, y before x)"
                         : first_difference(got, want)));
            REQUIRE(same_answer(got, want.hit));
        }
    }
    INFO(tests << " tests; in " << telling << " of them the earlier axis's frame gives other bits");
    CHECK(telling >= 100);
}
