// A heat map: what each pixel of a render cost (intersection tests, cells or nodes visited),
// drawn in colour beside a labelled colour scale. It is the picture that makes an accelerator
// visible: brute force is one flat colour (every ray tests every object), a grid or a tree shows
// where its rays do their work.
//
// The cost of a pixel is the growth of one of the thread's counters (stats.hpp) while its samples
// are traced: the render loop (render.hpp) keeps it when handed a map.
#pragma once

#include "common/image.hpp"
#include "common/stats.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rt {

struct CostMap {
    int width = 0, height = 0;
    Counter counter = Counter::intersection_tests;
    std::vector<std::uint64_t> cost;  // per pixel, row-major, top row first

    CostMap() = default;
    CostMap(int w, int h, Counter c) : width(w), height(h), counter(c), cost(static_cast<size_t>(w) * h, 0) {}

    std::uint64_t& at(int i, int j) { return cost[static_cast<size_t>(j) * width + i]; }
};

// The map's pixels as colours (viridis: dark blue for nothing, through green, to yellow at `top`
// and above), and beside them a colour bar labelled from 0 to `top` with `what` beneath: one image
// of the map's height. top <= 0 takes the map's 99.5th percentile, so a few costly pixels do not
// wash the rest out; either is rounded up to a round number (1, 2, 2.5 or 5 times a power of ten).
// With HeatScale::log, colours and bar follow log10(1 + cost) up to a power of ten: maps that
// differ a hundredfold (a uniform grid's and a BVH's) stay readable side by side on one scale.
enum class HeatScale { linear, log };
Image heat_image(const CostMap& map, const std::string& what, double top = 0.0, HeatScale scale = HeatScale::linear);

// The map's 99.5th percentile: heat_image's top when none is given. Maps drawn to be compared
// share one top, the largest of theirs.
double heat_top(const CostMap& map);

// a and b side by side (b to the right), on a dark background where their heights differ.
Image side_by_side(const Image& a, const Image& b);

// `a` above `b`, left-aligned, the narrower one padded with the background.
Image above_below(const Image& a, const Image& b);

// The viridis colour at v in [0, 1], linear RGB.
color viridis(float v);

// Draws `text` (stb_easy_font's small bitmap font, `scale` pixels a font pixel) with its top left
// corner at (x, y); returns the text's width in pixels.
int draw_text(Image& image, int x, int y, const std::string& text, const color& c, int scale = 2);

// A caption that reads over any picture: white text on a dark band, top left corner at (x, y),
// the font scaled to the image's height (1 below 160 pixels high). Drawn only where it fits: an
// image under 40 pixels high keeps its pixels.
void draw_label(Image& image, int x, int y, const std::string& text);

}  // namespace rt
