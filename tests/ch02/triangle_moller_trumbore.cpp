// EXERCISE 02.4: Moller-Trumbore: t, beta and gamma by Cramer's rule, rejecting early.
#include "tests/ch02/triangle_cases.hpp"

using namespace rt;
using namespace rt::grader;

RT_TRIANGLE_BEHAVIOURS(hit_triangle_moller_trumbore, "02.4")

STABILITY_TEST("hit_triangle_moller_trumbore: triangles whose determinant is exactly 0 are never hit", "02.4", 1)
{
    // Corners repeated as a == b or a == c, all equal, or lined up along an axis (pbrt-v4's
    // BadCase): det = e1.(v x e2) is then exactly 0. When b == c, or the corners line up along a
    // diagonal (triangles 2 and 4), rounding can leave det a tiny non-zero number and a ray aimed
    // at the sliver is "hit": the program's trade table measures how often (README, "The trade").
    triangles::degenerate(&hit_triangle_moller_trumbore<float>, {0, 1, 3, 5, 6});
}
