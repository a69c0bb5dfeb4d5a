// Chapter 01's figure, small, against the reference rendered from the solution.
#include "tests/ch01/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("01", "discs over a checkered floor", "01_ray_casting", rt::pictures::ch01(),
             "chapter 01's figure at 96x54, 1 sample per pixel")
