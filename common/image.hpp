// A linear RGB image and its way out to 8-bit sRGB.
// Pixel (i, j) is column i from the left and row j from the top, as PNG stores rows.
#pragma once

#include "common/vec.hpp"

#include <cstdint>
#include <vector>

namespace rt {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<color> pixels;  // row-major, top row first

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h, color(0.0f)) {}

    color& at(int i, int j) { return pixels[static_cast<size_t>(j) * width + i]; }
    const color& at(int i, int j) const { return pixels[static_cast<size_t>(j) * width + i]; }
};

// The sRGB transfer curve (IEC 61966-2-1) of one channel in [0, 1].
float srgb_encode(float linear);
float srgb_decode(float encoded);

// Tone map (clamp to [0, 1]) and encode as 8-bit sRGB, three bytes a pixel, top row first.
// A NaN or infinite pixel is a bug upstream: it becomes magenta (255, 0, 255), so it can never hide
// as black, and the programs' write_figure names it and exits 3 (a test writes one on purpose, so
// this is no assert).
std::vector<std::uint8_t> to_srgb8(const Image& image);

// The inverse, for reading reference images back: 8-bit sRGB to linear.
Image from_srgb8(const std::vector<std::uint8_t>& bytes, int width, int height);

// Count of pixels with a NaN or infinite channel.
int count_non_finite(const Image& image);

}  // namespace rt
