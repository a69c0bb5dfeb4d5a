#include "common/random.hpp"
#include "common/render.hpp"
#include "common/stats.hpp"
#include "common/trade.hpp"
#include "tests/grader/graded.hpp"

#include <set>

using namespace rt;

TEST_CASE("a pixel's random stream depends on the seed and the pixel only", "[common]")
{
    Rng a = pixel_rng(5, 3, 4, 10), b = pixel_rng(5, 3, 4, 10), other = pixel_rng(5, 4, 4, 10), reseeded = pixel_rng(6, 3, 4, 10);
    std::set<std::uint32_t> firsts;
    for (int k = 0; k < 100; ++k) {
        const std::uint32_t x = a.next_u32();
        CHECK(x == b.next_u32());
        firsts.insert(x);
    }
    CHECK(firsts.size() == 100);
    CHECK(other.next_u32() != pixel_rng(5, 3, 4, 10).next_u32());
    CHECK(reseeded.next_u32() != pixel_rng(5, 3, 4, 10).next_u32());
    Rng r(1, 2);
    for (int k = 0; k < 100000; ++k) {
        const float u = r.next_float();
        REQUIRE(u >= 0.0f);
        REQUIRE(u < 1.0f);
    }
}

TEST_CASE("the render loop gives the same image at 1 and 2 threads, and counts every sample", "[common]")
{
    RenderSettings s;
    s.width = 37;
    s.height = 23;
    s.spp = 5;
    s.show_progress = false;
    const auto radiance = [](float x, float y, Rng& rng) {
        count(Counter::primary_rays);
        return color(x * 0.01f, y * 0.02f, rng.next_float());
    };
    reset_counters();
    s.threads = 1;
    const Image one = render(s, radiance);
    CHECK(total_counts()[size_t(Counter::primary_rays)] == 37u * 23u * 5u);
    s.threads = 2;
    const Image two = render(s, radiance);
    CHECK(one.pixels == two.pixels);
    s.seed = 2;
    CHECK(render(s, radiance).pixels != one.pixels);
}

TEST_CASE("one sample per pixel lands on the pixel centre; more spread over the pixel", "[common]")
{
    Rng rng(1, 1);
    const PixelSample centre = sample_position(4, 7, 1, rng);
    CHECK(centre.x == 4.0f);
    CHECK(centre.y == 7.0f);
    float lo = 1, hi = -1;
    for (int k = 0; k < 1000; ++k) {
        const PixelSample p = sample_position(4, 7, 16, rng);
        REQUIRE(std::abs(p.x - 4.0f) <= 0.5f);
        REQUIRE(std::abs(p.y - 7.0f) <= 0.5f);
        lo = std::min(lo, p.x - 4.0f);
        hi = std::max(hi, p.x - 4.0f);
    }
    CHECK(lo < -0.45f);
    CHECK(hi > 0.45f);
}

TEST_CASE("rmse is zero for equal images and the channel difference for a uniform offset", "[common]")
{
    Image a(4, 4), b(4, 4);
    CHECK(rmse(a, b) == 0.0);
    for (color& c : b.pixels)
        c = color(0.1f, 0.1f, 0.1f);
    CHECK(rmse(a, b) == Approx(0.1).epsilon(1e-6));
    int calls = 0;
    const Timing t = time_runs(3, [&] { ++calls; });
    CHECK(calls == 3);
    CHECK(t.runs == 3);
    CHECK((0.0 <= t.min && t.min <= t.median && t.median <= t.max));
}
