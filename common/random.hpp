// Deterministic random streams, one per pixel, so an image is the same at any thread count:
// a pixel's samples depend only on (seed, pixel), never on which thread drew them or in what order.
//
// The generator is PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically
// Good Algorithms for Random Number Generation", XSH-RR variant): 16 bytes of state, and each pixel
// gets its own stream (increment) rather than a shared sequence. std::mt19937 would need 2.5 KB of
// state seeded per pixel, and std's distributions differ between standard libraries.
#pragma once

#include <cstdint>

namespace rt {

class Rng {
public:
    Rng(std::uint64_t seed, std::uint64_t stream)
        : state_(0), inc_((stream << 1u) | 1u)
    {
        next_u32();
        state_ += seed;
        next_u32();
    }

    std::uint32_t next_u32()
    {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        const auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, so every value is exactly representable and 1 is never hit.
    float next_float() { return static_cast<float>(next_u32() >> 8) * 0x1p-24f; }

private:
    std::uint64_t state_;
    std::uint64_t inc_;
};

// The stream of pixel (i, j) of an image `width` pixels wide.
inline Rng pixel_rng(std::uint64_t seed, int i, int j, int width)
{
    return Rng(seed, static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(width) + static_cast<std::uint64_t>(i));
}

}  // namespace rt
