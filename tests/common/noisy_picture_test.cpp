// The grader's comparison of noisy pictures: correct renders pass at any seed and sample count,
// a wrong brightness fails even at few samples.
#include "common/png.hpp"
#include "common/render.hpp"
#include "tests/grader/graded.hpp"
#include "tests/grader/picture.hpp"

#include <filesystem>

using namespace rt;

namespace {

// A picture with structure and noise: left half dim, right half bright, each sample uniform
// around its pixel's mean, so every pixel has a known spread.
color noisy(float x, float, Rng& rng, float gain)
{
    const float base = x < 24.0f ? 0.15f : 0.55f;
    return color(gain * (base + 0.3f * (rng.next_float() - 0.5f)));
}

Image render_noisy(int spp, std::uint64_t seed, float gain, Image* variance)
{
    RenderSettings s;
    s.width = 48;
    s.height = 32;
    s.spp = spp;
    s.seed = seed;
    s.show_progress = false;
    return render(s, [gain](float x, float y, Rng& rng) { return noisy(x, y, rng, gain); }, variance);
}

struct ReferenceDir {
    ReferenceDir()
    {
        saved = grader::references_dir;
        grader::references_dir = (std::filesystem::temp_directory_path() / "rt_kit_noisy_test").string();
        grader::artifacts_dir = grader::references_dir + "/failures";
        write_png(grader::reference_path("noisy"), render_noisy(1024, 99, 1.0f, nullptr));
    }
    ~ReferenceDir() { grader::references_dir = saved; }
    std::string saved;
};

}  // namespace

TEST_CASE("a correct noisy render matches its reference at every seed tried, at 4 and 16 spp", "[common]")
{
    const ReferenceDir dir;
    for (const int spp : {4, 16})
        for (std::uint64_t seed = 1; seed <= 20; ++seed) {
            Image variance;
            const Image image = render_noisy(spp, seed, 1.0f, &variance);
            grader::NoisyTolerance tol;
            tol.spp = spp;
            const grader::PictureVerdict verdict = grader::compare_noisy_with_reference(image, variance, "noisy", tol);
            INFO(spp << " spp, seed " << seed << ": " << verdict.report);
            CHECK(verdict.matches);
        }
}

TEST_CASE("a noisy render 10% too bright fails even at 4 spp", "[common]")
{
    const ReferenceDir dir;
    for (const int spp : {4, 16}) {
        Image variance;
        const Image image = render_noisy(spp, 5, 1.1f, &variance);
        grader::NoisyTolerance tol;
        tol.spp = spp;
        const grader::PictureVerdict verdict = grader::compare_noisy_with_reference(image, variance, "noisy", tol);
        INFO(spp << " spp: " << verdict.report);
        CHECK_FALSE(verdict.matches);
    }
}
