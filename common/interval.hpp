// The range of t a query accepts. Queries shrink `max` to the closest hit found so far,
// which is how "if (object.distance < distance)" of the slides' QueryScene reads with an interval.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

namespace rt {

constexpr float infinity = std::numeric_limits<float>::infinity();

// Why 1e-4: chapter 01's rays start at the eye, never on a surface, so any small positive bound
// works; chapter 04 measures what a fixed bound like this costs for rays that start on a surface.
constexpr float t_min_default = 1e-4f;

// Over the scalar type T, like BasicRay; the kit's queries use float, `Interval`.
template <class T>
struct BasicInterval {
    T min = static_cast<T>(t_min_default);
    T max = std::numeric_limits<T>::infinity();

    // Open at both ends: a hit exactly at min or max is outside, so a ray never re-finds the
    // closest hit it already holds (max) nor a surface it starts on (min). A NaN is never inside.
    bool surrounds(T t) const { return min < t && t < max; }
};

using Interval = BasicInterval<float>;

// The next float above x: std::nextafter(x, infinity), for every x (NaN and infinity themselves),
// written out because the library's is a call into libm that no compiler inlines, and a query asks
// for it at every new best hit (2% of the wide tree's instructions on the pyramid, by callgrind). A
// float's bits, read as an integer, count its values in order away from zero on either side.
inline float next_up(float x)
{
    if (!(x < infinity))
        return x;
    if (x == 0.0f)
        return std::numeric_limits<float>::denorm_min();  // from -0 too
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = x > 0.0f ? bits + 1u : bits - 1u;
    std::memcpy(&x, &bits, sizeof bits);
    return x;
}

// The next float below x: std::nextafter(x, -infinity), by the symmetry of floats about 0.
inline float next_down(float x) { return -next_up(-x); }

}  // namespace rt
