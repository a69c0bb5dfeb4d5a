// Chapter 02's figure, small, against the reference rendered from the solution. It renders with
// the kit's default tests: the precise sphere (02.2), Moller-Trumbore (02.4) and the normals (02.6).
#include "tests/ch02/picture.hpp"
#include "tests/grader/picture_test.hpp"

PICTURE_TEST("02", "spheres and triangle meshes, headlight-shaded", "02_spheres_triangles", rt::pictures::ch02(),
             "chapter 02's figure at 96x54, 1 sample per pixel")
