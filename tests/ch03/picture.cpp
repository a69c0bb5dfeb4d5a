// Chapter 03's figure, small, against the reference rendered from the solution. It renders with
// the kit's default trace settings (depth 8, weight cut-off 1e-3, exact Fresnel), so every
// exercise of the chapter shows in it.
#include "tests/ch03/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("03", "a mirror and a glass sphere over a checkered floor", "03_reflection_refraction",
             rt::pictures::ch03(), "chapter 03's figure at 96x54, 1 sample per pixel")
