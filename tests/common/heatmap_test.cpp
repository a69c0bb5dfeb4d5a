// The heat map (common/heatmap.hpp): its colours follow the scale, linear or logarithmic, a shared
// top puts maps on one scale, a map too low for its colour bar is still drawn, and a label reads
// over any picture.
#include "common/heatmap.hpp"
#include "tests/grader/graded.hpp"

using namespace rt;

namespace {

CostMap ramp(int w, int h)
{
    CostMap map(w, h, Counter::intersection_tests);
    for (size_t k = 0; k < map.cost.size(); ++k)
        map.cost[k] = k;
    return map;
}

bool same(const color& a, const color& b) { return glm::all(glm::lessThan(glm::abs(a - b), vec3(1e-6f))); }

}  // namespace

TEST_CASE("a heat map colours 0 as the scale's bottom and its top as the scale's top, linear or logarithmic")
{
    CostMap map(4, 60, Counter::intersection_tests);
    map.cost[1] = 100;
    map.cost[2] = 10;
    for (const HeatScale scale : {HeatScale::linear, HeatScale::log}) {
        const Image image = heat_image(map, "tests", 100.0, scale);
        INFO((scale == HeatScale::log ? "log" : "linear") << " scale up to 100");
        CHECK(image.height == 60);
        CHECK(same(image.at(0, 0), viridis(0.0f)));
        CHECK(same(image.at(1, 0), viridis(1.0f)));
        // 10 of 100: a tenth of a linear bar; log10(11) / log10(101), about half, of a logarithmic one.
        const float expected = scale == HeatScale::log ? static_cast<float>(std::log10(11.0) / std::log10(101.0)) : 0.1f;
        CHECK(same(image.at(2, 0), viridis(expected)));
    }
}

TEST_CASE("maps drawn with one top share one scale; without one each takes its 99.5th percentile")
{
    const CostMap small = ramp(10, 50), large = ramp(20, 50);
    CHECK(heat_top(small) == 497.0);
    CHECK(heat_top(large) == 995.0);
    const double top = std::max(heat_top(small), heat_top(large));
    const Image a = heat_image(small, "a", top), b = heat_image(large, "b", top);
    // The same cost, the same colour, on either map.
    CHECK(same(a.at(5, 10), b.at(5, 5)));
}

TEST_CASE("a heat map only a few pixels high is drawn without its colour bar, and does not write past the image")
{
    for (const int h : {1, 8, 40}) {
        const Image image = heat_image(ramp(6, h), "tests per pixel");
        INFO("a map 6 x " << h);
        CHECK(image.height == h);
        CHECK(image.width > 6);
    }
}

TEST_CASE("a label darkens a band under white text and an image too low for one keeps its pixels")
{
    Image tall(200, 80);
    for (color& c : tall.pixels)
        c = color(0.8f);
    draw_label(tall, 5, 5, "area lights");
    int white = 0, darkened = 0;
    for (int j = 0; j < tall.height; ++j)
        for (int i = 0; i < tall.width; ++i) {
            const color c = tall.at(i, j);
            white += same(c, color(1.0f));
            darkened += same(c, color(0.2f));
            if (!same(c, color(0.8f)))
                CHECK((i >= 5 && j >= 5 && j < 5 + 7 + 4));  // only inside the label's band
        }
    CHECK(white > 20);
    CHECK(darkened > white);
    CHECK(same(tall.at(4, 6), color(0.8f)));  // left of the band

    Image low(200, 39);
    for (color& c : low.pixels)
        c = color(0.8f);
    draw_label(low, 5, 5, "area lights");
    for (const color& c : low.pixels)
        REQUIRE(same(c, color(0.8f)));
}
