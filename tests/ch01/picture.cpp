// Chapter 01's figure, small, against the reference rendered from the solution.
#include "tests/ch01/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (discs over a checkered floor) matches the reference picture", "01.P", 3)
{
    const Image image = pictures::ch01();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "01_ray_casting");
    INFO("chapter 01's figure at 96x54, 1 sample per pixel: " << verdict.report);
    CHECK(verdict.matches);
}
