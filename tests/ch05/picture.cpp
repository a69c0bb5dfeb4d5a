// Chapter 05's figure, small and noisy, against the reference rendered from the solution at many
// more samples per pixel. The comparison is by blocks, each allowed 5 standard errors of its own
// noise (the render's variance of the mean, and the reference's, from the sample counts): a
// correct render passes at any seed, a light weighted wrongly (too bright or dim by a constant, or
// by a slant) moves whole regions by many standard errors.
#include "tests/ch05/picture.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

using namespace rt;

GRADED_TEST("the figure (a hard shadow from a point light beside soft shadows from area lights) matches the reference picture", "05.P", 3)
{
    Image variance;
    const Image image = pictures::ch05(pictures::ch05_test_spp, &variance);
    grader::NoisyTolerance tolerance;
    tolerance.spp = pictures::ch05_test_spp;
    tolerance.reference_spp = pictures::ch05_reference_spp;
    const grader::PictureVerdict verdict =
        grader::compare_noisy_with_reference(image, variance, "05_soft_shadows", tolerance);
    INFO("chapter 05's figure at " << pictures::ch05_width << "x" << pictures::ch05_height << ", "
         << pictures::ch05_test_spp << " samples per pixel, 4 stratified samples per light: " << verdict.report);
    CHECK(verdict.matches);
}
