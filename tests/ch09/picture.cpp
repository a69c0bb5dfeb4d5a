// Chapter 09's figure, small, against the reference rendered from the solution (brute force's
// picture, since the hashed grid changes no answer).
#include "tests/ch09/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("09", "the teapot in a stadium through the hashed grid", "09_hashed_voxels", rt::pictures::ch09(),
             "chapter 09's figure at 96x54, 1 sample per pixel, through your hashed grid")
