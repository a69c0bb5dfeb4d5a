// EXERCISE 02.5: the watertight test of Woop, Benthin and Wald (JCGT 2013).
#include "tests/ch02/triangle_cases.hpp"

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
