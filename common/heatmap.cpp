#include "common/heatmap.hpp"

#include <stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace rt {

namespace {

// Viridis (van der Walt and Smith, matplotlib's default colour map since 2015: perceptually
// uniform, readable in grey and by colour-blind readers), sampled at nine evenly spaced points in
// sRGB and joined linearly.
constexpr float viridis_srgb[9][3] = {
    {0.267f, 0.005f, 0.329f}, {0.278f, 0.175f, 0.483f}, {0.230f, 0.322f, 0.546f},
    {0.172f, 0.449f, 0.558f}, {0.128f, 0.567f, 0.551f}, {0.153f, 0.683f, 0.498f},
    {0.361f, 0.786f, 0.388f}, {0.667f, 0.862f, 0.196f}, {0.993f, 0.906f, 0.144f}};

// A label's number: whole numbers as they are, others to three significant digits.
std::string label(double v)
{
    std::ostringstream s;
    if (v == std::floor(v) && v < 1e7)
        s << static_cast<long long>(v);
    else
        s << std::setprecision(3) << v;
    return s.str();
}

// The least of 1, 2, 2.5, 5 times a power of ten that is at least x: a scale's top whose quarters
// are round numbers.
double nice_ceiling(double x)
{
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    for (const double m : {1.0, 2.0, 2.5, 5.0})
        if (m * p >= x)
            return m * p;
    return 10.0 * p;
}

}  // namespace

color viridis(float v)
{
    const float x = std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 8.0f;
    const int k = std::min(7, static_cast<int>(x));
    const float f = x - static_cast<float>(k);
    color c;
    for (int ch = 0; ch < 3; ++ch)
        c[ch] = srgb_decode((1.0f - f) * viridis_srgb[k][ch] + f * viridis_srgb[k + 1][ch]);
    return c;
}

int draw_text(Image& image, int x, int y, const std::string& text, const color& c, int scale)
{
    // stb_easy_font draws characters as axis-aligned quads, four vertices of 16 bytes each.
    static thread_local std::vector<char> buffer(64 * 1024);
    std::vector<char> copy(text.begin(), text.end());
    copy.push_back('\0');
    const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
    for (int q = 0; q < quads; ++q) {
        const float* v0 = reinterpret_cast<const float*>(buffer.data() + q * 64);
        const float* v2 = reinterpret_cast<const float*>(buffer.data() + q * 64 + 32);
        for (int j = static_cast<int>(v0[1]) * scale; j < static_cast<int>(v2[1]) * scale; ++j)
            for (int i = static_cast<int>(v0[0]) * scale; i < static_cast<int>(v2[0]) * scale; ++i)
                if (x + i >= 0 && x + i < image.width && y + j >= 0 && y + j < image.height)
                    image.at(x + i, y + j) = c;
    }
    return stb_easy_font_width(copy.data()) * scale;
}

void draw_label(Image& image, int x, int y, const std::string& text)
{
    if (image.height < 40)
        return;
    const int scale = std::max(1, image.height / 160);
    std::vector<char> probe(text.begin(), text.end());
    probe.push_back('\0');
    const int pad = 2 * scale, width = stb_easy_font_width(probe.data()) * scale, height = 7 * scale;
    for (int j = std::max(0, y); j < std::min(image.height, y + height + 2 * pad); ++j)
        for (int i = std::max(0, x); i < std::min(image.width, x + width + 2 * pad); ++i)
            image.at(i, j) = 0.25f * image.at(i, j);
    draw_text(image, x + pad, y + pad, text, color(1.0f), scale);
}

double heat_top(const CostMap& map)
{
    if (map.cost.empty())
        return 0.0;
    std::vector<std::uint64_t> sorted = map.cost;
    const size_t k = std::min(sorted.size() - 1, static_cast<size_t>(0.995 * static_cast<double>(sorted.size())));
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(k), sorted.end());
    return static_cast<double>(sorted[k]);
}

Image heat_image(const CostMap& map, const std::string& what, double top, HeatScale scale)
{
    if (top <= 0.0)
        top = heat_top(map);
    const bool log_scale = scale == HeatScale::log;
    top = log_scale ? std::pow(10.0, std::ceil(std::log10(std::max(top, 10.0)))) : nice_ceiling(std::max(top, 1.0));
    // Where a cost lies on the bar, 0 at its bottom and 1 at its top.
    const auto level = [&](double cost) {
        return static_cast<float>(log_scale ? std::log10(1.0 + cost) / std::log10(1.0 + top) : cost / top);
    };
    // The map, then a bar 24 pixels wide with tick labels to its right, and the caption under them,
    // at the tick labels' size where the map is tall enough, so that a projected slide can read it.
    constexpr int gap = 12, bar = 24, label_room = 200;
    const int h = map.height;
    const int caption_scale = h >= 240 ? 2 : 1, line_height = 10 * caption_scale;
    const int x0 = map.width + gap, room = bar + label_room - 4;
    std::vector<std::string> lines;
    for (size_t start = 0; start < what.size();) {
        // As many words as fit on the line; a word longer than the line gets one of its own.
        size_t end = what.size(), cut = std::string::npos;
        for (size_t k = start; k <= what.size(); ++k)
            if (k == what.size() || what[k] == ' ') {
                std::vector<char> probe(what.begin() + static_cast<long>(start), what.begin() + static_cast<long>(k));
                probe.push_back('\0');
                if (stb_easy_font_width(probe.data()) * caption_scale > room && cut != std::string::npos)
                    break;
                cut = k;
            }
        end = cut == std::string::npos ? what.size() : cut;
        lines.push_back(what.substr(start, end - start));
        start = end + 1;
    }
    Image image(map.width + gap + bar + label_room, h);
    const color background(0.02f);
    for (color& c : image.pixels)
        c = background;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < map.width; ++i)
            image.at(i, j) = viridis(level(static_cast<double>(map.cost[static_cast<size_t>(j) * map.width + i])));
    // The bar runs from `top` at its top to 0 at its bottom, with room for the caption below it; a
    // map too low for one (a render a few pixels high) goes without.
    const int bar_top = 8, bar_bottom = h - 14 - line_height * static_cast<int>(lines.size());
    if (bar_bottom < bar_top + 2)
        return image;
    for (int j = bar_top; j <= bar_bottom; ++j)
        for (int i = x0; i < x0 + bar; ++i)
            image.at(i, j) = viridis(static_cast<float>(bar_bottom - j) / static_cast<float>(bar_bottom - bar_top));
    const color ink(0.9f);
    // Ticks at quarters of a linear bar; at 0 and each power of ten of a logarithmic one.
    std::vector<double> ticks;
    if (log_scale) {
        ticks.push_back(0.0);
        for (double v = 10.0; v <= top; v *= 10.0)
            ticks.push_back(v);
    } else {
        for (int t = 0; t <= 4; ++t)
            ticks.push_back(top * t / 4);
    }
    for (const double v : ticks) {
        const int j = bar_bottom - static_cast<int>(std::lround(static_cast<float>(bar_bottom - bar_top) * level(v)));
        for (int i = x0 + bar; i < x0 + bar + 5; ++i)
            image.at(i, j) = ink;
        const std::string text = label(v) + (v == top ? "+" : "");
        draw_text(image, x0 + bar + 8, j - 6, text, ink);
    }
    for (size_t k = 0; k < lines.size(); ++k)
        draw_text(image, x0, bar_bottom + 10 + line_height * static_cast<int>(k), lines[k], ink, caption_scale);
    return image;
}

// `b` placed to the right of `a` or under it, on the maps' background.
static Image joined(const Image& a, const Image& b, bool below)
{
    const int bx = below ? 0 : a.width, by = below ? a.height : 0;
    Image image(std::max(a.width, bx + b.width), std::max(a.height, by + b.height));
    for (color& c : image.pixels)
        c = color(0.02f);
    for (int j = 0; j < a.height; ++j)
        for (int i = 0; i < a.width; ++i)
            image.at(i, j) = a.at(i, j);
    for (int j = 0; j < b.height; ++j)
        for (int i = 0; i < b.width; ++i)
            image.at(bx + i, by + j) = b.at(i, j);
    return image;
}

Image above_below(const Image& a, const Image& b)
{
    return joined(a, b, true);
}

Image side_by_side(const Image& a, const Image& b)
{
    return joined(a, b, false);
}

}  // namespace rt
