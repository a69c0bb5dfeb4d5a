// Chapter 06's figure, small, against the reference rendered from the solution at many samples,
// within the noise that follows from the sample counts.
#include "tests/ch06/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (a row of spheres, the middle one in focus) matches the reference within its noise", "06.P", 4)
{
    constexpr int spp = 16;
    Image variance;
    const Image image = pictures::ch06_render(spp, 2, &variance);
    grader::NoisyTolerance tolerance;
    tolerance.spp = spp;
    tolerance.reference_spp = pictures::ch06_reference_spp;
    const grader::PictureVerdict verdict =
        grader::compare_noisy_with_reference(image, variance, "06_depth_of_field", tolerance);
    INFO("chapter 06's figure at " << pictures::ch06_width << "x" << pictures::ch06_height << ", " << spp
         << " samples per pixel (each from its own point of the lens): " << verdict.report);
    CHECK(verdict.matches);
}
