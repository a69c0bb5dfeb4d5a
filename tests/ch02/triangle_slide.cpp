// EXERCISE 02.3: the slide's triangle test: the plane's t, then the same-sign test of three cross products.
#include "tests/ch02/triangle_cases.hpp"

using namespace rt;
using namespace rt::grader;

RT_TRIANGLE_BEHAVIOURS(hit_triangle_slide, "02.3")

STABILITY_TEST("hit_triangle_slide: triangles without area are never hit (n = 0 makes n.v = 0)", "02.3", 1)
{
    triangles::degenerate(&hit_triangle_slide<float>, {0, 1, 2, 3, 4, 5, 6});
}
