// PNG files through stb_image_write and stb_image (compiled once, in stb.cpp).
#pragma once

#include "common/image.hpp"

#include <string>

namespace rt {

// Writes the image as an 8-bit sRGB PNG, creating missing parent folders.
// Throws InputError naming the path when it cannot be written.
void write_png(const std::string& path, const Image& image);

// Reads an 8-bit PNG (grey, RGB or RGBA; alpha ignored) back to linear RGB.
// Throws InputError naming the path when it is missing or not a PNG.
Image read_png(const std::string& path);

// The raw 8-bit sRGB bytes of a PNG, for comparisons that must not round-trip through floats.
std::vector<std::uint8_t> read_png_bytes(const std::string& path, int& width, int& height);

}  // namespace rt
