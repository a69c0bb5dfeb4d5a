#include "common/image.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

float srgb_encode(float linear)
{
    const float x = std::clamp(linear, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

float srgb_decode(float encoded)
{
    const float x = std::clamp(encoded, 0.0f, 1.0f);
    return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

static bool finite(const color& c)
{
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

std::vector<std::uint8_t> to_srgb8(const Image& image)
{
    std::vector<std::uint8_t> bytes;
    bytes.reserve(image.pixels.size() * 3);
    for (const color& c : image.pixels) {
        if (!finite(c)) {
            bytes.insert(bytes.end(), {255, 0, 255});
            continue;
        }
        for (int k = 0; k < 3; ++k)
            bytes.push_back(static_cast<std::uint8_t>(std::lround(255.0f * srgb_encode(c[k]))));
    }
    return bytes;
}

Image from_srgb8(const std::vector<std::uint8_t>& bytes, int width, int height)
{
    Image image(width, height);
    for (size_t p = 0; p < image.pixels.size(); ++p)
        for (int k = 0; k < 3; ++k)
            image.pixels[p][k] = srgb_decode(bytes[3 * p + k] / 255.0f);
    return image;
}

int count_non_finite(const Image& image)
{
    return static_cast<int>(std::count_if(image.pixels.begin(), image.pixels.end(),
                                          [](const color& c) { return !finite(c); }));
}

}  // namespace rt
