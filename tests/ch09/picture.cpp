// Chapter 09's figure, small, against the reference rendered from the solution (brute force's
// picture, since the hashed grid changes no answer).
#include "tests/ch09/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (the teapot in a stadium through the hashed grid) matches the reference picture", "09.P", 3)
{
    const Image image = pictures::ch09();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "09_hashed_voxels");
    INFO("chapter 09's figure at 96x54, 1 sample per pixel, through your hashed grid: " << verdict.report);
    CHECK(verdict.matches);
}
