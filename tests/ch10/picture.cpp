// Chapter 10's figure, small, against the reference rendered from the solution (brute force's
// picture, since the BVH changes no answer).
#include "tests/ch10/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("10", "the teapot in a stadium through the BVH", "10_hierarchies", rt::pictures::ch10(),
             "chapter 10's figure at 96x54, 1 sample per pixel, through your BVH")
