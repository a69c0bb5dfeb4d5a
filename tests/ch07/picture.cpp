// Chapter 07's figure, small, against the reference rendered from the solution (and so, since the
// grid answers every ray as brute force does, brute force's picture).
#include "tests/ch07/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("07", "the fractal mountain through the grid", "07_uniform_grid", rt::pictures::ch07(),
             "chapter 07's figure at 96x54, 1 sample per pixel, 32772 objects through your grid")
