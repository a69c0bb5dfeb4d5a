// Chapter 02's figure, small, against the reference rendered from the solution. It renders with
// the kit's default tests: the precise sphere (02.2), Moller-Trumbore (02.4) and the normals (02.6).
#include "tests/ch02/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (spheres and triangle meshes, headlight-shaded) matches the reference picture", "02.P", 3)
{
    const Image image = pictures::ch02();
    const grader::PictureVerdict verdict = grader::compare_with_reference(image, "02_spheres_triangles");
    INFO("chapter 02's figure at 96x54, 1 sample per pixel: " << verdict.report);
    CHECK(verdict.matches);
}
