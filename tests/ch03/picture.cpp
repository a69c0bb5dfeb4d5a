// Chapter 03's figure, small, against the reference rendered from the solution. It renders with
// the kit's default trace settings (depth 8, weight cut-off 1e-3, exact Fresnel), so every
// exercise of the chapter shows in it.
#include "tests/ch03/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (a mirror and a glass sphere over a checkered floor) matches the reference picture", "03.P", 3)
{
    const Image image = pictures::ch03();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "03_reflection_refraction");
    INFO("chapter 03's figure at 96x54, 1 sample per pixel: " << verdict.report);
    CHECK(verdict.matches);
}
