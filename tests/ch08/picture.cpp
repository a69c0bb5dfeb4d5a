// Chapter 08's figure, small, against the reference rendered from the solution (brute force's
// picture, since the mailboxes change no answer).
#include "tests/ch08/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("08", "the sticks through the grid with mailboxes", "08_mailboxing", rt::pictures::ch08(),
             "chapter 08's figure at 96x54, 1 sample per pixel, 8002 objects through your grid with mailboxes")
