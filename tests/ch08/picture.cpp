// Chapter 08's figure, small, against the reference rendered from the solution (brute force's
// picture, since the mailboxes change no answer).
#include "tests/ch08/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (the sticks through the grid with mailboxes) matches the reference picture", "08.P", 3)
{
    const Image image = pictures::ch08();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "08_mailboxing");
    INFO("chapter 08's figure at 96x54, 1 sample per pixel, 8002 objects through your grid with mailboxes: " << verdict.report);
    CHECK(verdict.matches);
}
