// Chapter 07's figure, small, against the reference rendered from the solution (and so, since the
// grid answers every ray as brute force does, brute force's picture).
#include "tests/ch07/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (the fractal mountain through the grid) matches the reference picture", "07.P", 3)
{
    const Image image = pictures::ch07();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "07_uniform_grid");
    INFO("chapter 07's figure at 96x54, 1 sample per pixel, 32772 objects through your grid: " << verdict.report);
    CHECK(verdict.matches);
}
