// Chapter 04's figure, small, against the reference rendered from the solution. It renders with
// the kit's defaults: the robust offset (04.3) and the any-hit feeler (04.2), shaded by 04.1 and 04.4.
#include "tests/ch04/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("04", "a sphere with a hard shadow from a point light", "04_shadow_feelers", rt::pictures::ch04(),
             "chapter 04's figure at 96x54, 1 sample per pixel")
