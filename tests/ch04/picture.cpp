// Chapter 04's figure, small, against the reference rendered from the solution. It renders with
// the kit's defaults: the robust offset (04.3) and the any-hit feeler (04.2), shaded by 04.1 and 04.4.
#include "tests/ch04/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (a sphere with a hard shadow from a point light) matches the reference picture", "04.P", 3)
{
    const Image image = pictures::ch04();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "04_shadow_feelers");
    INFO("chapter 04's figure at 96x54, 1 sample per pixel: " << verdict.report);
    CHECK(verdict.matches);
}
