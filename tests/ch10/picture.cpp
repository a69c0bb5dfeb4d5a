// Chapter 10's figure, small, against the reference rendered from the solution (brute force's
// picture, since the BVH changes no answer).
#include "tests/ch10/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (the teapot in a stadium through the BVH) matches the reference picture", "10.P", 3)
{
    const Image image = pictures::ch10();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "10_hierarchies");
    INFO("chapter 10's figure at 96x54, 1 sample per pixel, through your BVH: " << verdict.report);
    CHECK(verdict.matches);
}
