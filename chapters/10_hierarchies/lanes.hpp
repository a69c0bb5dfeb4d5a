// Four floats at once (given): SSE on every x86-64 compiler (GCC, Clang, MSVC, MinGW); elsewhere
// (ARM: Apple silicon) the same arithmetic lane by lane in plain C++, not measured here.
// RT_WIDE_SCALAR forces the plain one, so a test can check that both agree. The wide tree's
// four-box test (wide_bvh.hpp) and the four-triangle test (EXERCISE 10.6) run on it.
//
// Why the answers are the scalar code's, bit for bit: SSE's add, subtract, multiply and divide are
// IEEE single precision, lane by lane, rounded as the scalar operations are, and its compares are
// the scalar compares (false for NaN; != true for it). So a formula written once with Float4 in
// place of float gives in each lane what the scalar formula gives, as long as it keeps the scalar
// formula's order of operations and neither is fused into multiply-adds (the kit builds with
// -ffp-contract=off). That holds wherever float arithmetic is single precision: every 64-bit
// processor, not 32-bit x86's x87, which the kit does not support.
#pragma once

#include <cmath>

#if !defined(RT_WIDE_SCALAR) && (defined(__SSE2__) || defined(_M_X64)) && !defined(_M_ARM64EC)
#define RT_WIDE_SSE 1
#include <emmintrin.h>
#else
#define RT_WIDE_SSE 0
#endif

namespace rt {

// Which of the two this program runs, for messages.
constexpr const char* lanes_kind = RT_WIDE_SSE ? "SSE" : "plain C++";

// The two kinds under two names, so that Float4's and Mask4's own functions built one way are never
// taken for the other's. The code written on them (the four-box test, the wide tree, 10.6) has one
// name either way: a program builds it all one way, as the kit's tests build each variant.
#if RT_WIDE_SSE
inline namespace lanes_sse {
#else
inline namespace lanes_plain {
#endif

// Four yes-or-no answers, one a lane (what comparing two Float4 gives).
struct Mask4 {
#if RT_WIDE_SSE
    __m128 v;
#else
    unsigned v;  // bit i: lane i
#endif
};

// Four floats, one a lane.
struct Float4 {
#if RT_WIDE_SSE
    __m128 v;
    Float4(float x) : v(_mm_set1_ps(x)) {}  // every lane x
    Float4(float a, float b, float c, float d) : v(_mm_setr_ps(a, b, c, d)) {}  // lanes 0, 1, 2, 3
    explicit Float4(__m128 x) : v(x) {}
    static Float4 load(const float* p) { return Float4(_mm_loadu_ps(p)); }  // p[0 .. 4)
    void store(float* p) const { _mm_storeu_ps(p, v); }
#else
    float v[4];
    Float4(float x) : v{x, x, x, x} {}
    static Float4 load(const float* p) { return Float4(p[0], p[1], p[2], p[3]); }
    void store(float* p) const
    {
        for (int i = 0; i < 4; ++i)
            p[i] = v[i];
    }
    Float4(float a, float b, float c, float d) : v{a, b, c, d} {}
#endif
};

#if RT_WIDE_SSE
inline Float4 operator+(Float4 a, Float4 b) { return Float4(_mm_add_ps(a.v, b.v)); }
inline Float4 operator-(Float4 a, Float4 b) { return Float4(_mm_sub_ps(a.v, b.v)); }
inline Float4 operator*(Float4 a, Float4 b) { return Float4(_mm_mul_ps(a.v, b.v)); }
inline Float4 operator/(Float4 a, Float4 b) { return Float4(_mm_div_ps(a.v, b.v)); }
inline Mask4 operator<(Float4 a, Float4 b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline Mask4 operator>(Float4 a, Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
inline Mask4 operator<=(Float4 a, Float4 b) { return {_mm_cmple_ps(a.v, b.v)}; }
inline Mask4 operator==(Float4 a, Float4 b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
inline Mask4 operator!=(Float4 a, Float4 b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
inline Mask4 operator&(Mask4 a, Mask4 b) { return {_mm_and_ps(a.v, b.v)}; }
inline Mask4 operator|(Mask4 a, Mask4 b) { return {_mm_or_ps(a.v, b.v)}; }
inline Mask4 operator~(Mask4 a) { return {_mm_xor_ps(a.v, _mm_castsi128_ps(_mm_set1_epi32(-1)))}; }
// The lanes that are true, as bits: bit i for lane i.
inline unsigned bits(Mask4 m) { return static_cast<unsigned>(_mm_movemask_ps(m.v)); }
// a > b ? a : b and a < b ? a : b, lane by lane: b where either is NaN (SSE's maxps and minps).
inline Float4 greater_or_second(Float4 a, Float4 b) { return Float4(_mm_max_ps(a.v, b.v)); }
inline Float4 less_or_second(Float4 a, Float4 b) { return Float4(_mm_min_ps(a.v, b.v)); }
// |a|, lane by lane: the sign bit cleared.
inline Float4 abs(Float4 a) { return Float4(_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)); }
#else
namespace lanes_detail {
template <class F>
Float4 each(Float4 a, Float4 b, F f)
{
    return Float4(f(a.v[0], b.v[0]), f(a.v[1], b.v[1]), f(a.v[2], b.v[2]), f(a.v[3], b.v[3]));
}
template <class F>
Mask4 compare(Float4 a, Float4 b, F f)
{
    unsigned m = 0;
    for (int i = 0; i < 4; ++i)
        m |= (f(a.v[i], b.v[i]) ? 1u : 0u) << i;
    return {m};
}
}  // namespace lanes_detail
inline Float4 operator+(Float4 a, Float4 b) { return lanes_detail::each(a, b, [](float x, float y) { return x + y; }); }
inline Float4 operator-(Float4 a, Float4 b) { return lanes_detail::each(a, b, [](float x, float y) { return x - y; }); }
inline Float4 operator*(Float4 a, Float4 b) { return lanes_detail::each(a, b, [](float x, float y) { return x * y; }); }
inline Float4 operator/(Float4 a, Float4 b) { return lanes_detail::each(a, b, [](float x, float y) { return x / y; }); }
inline Mask4 operator<(Float4 a, Float4 b) { return lanes_detail::compare(a, b, [](float x, float y) { return x < y; }); }
inline Mask4 operator>(Float4 a, Float4 b) { return lanes_detail::compare(a, b, [](float x, float y) { return x > y; }); }
inline Mask4 operator<=(Float4 a, Float4 b) { return lanes_detail::compare(a, b, [](float x, float y) { return x <= y; }); }
inline Mask4 operator==(Float4 a, Float4 b) { return lanes_detail::compare(a, b, [](float x, float y) { return x == y; }); }
inline Mask4 operator!=(Float4 a, Float4 b) { return lanes_detail::compare(a, b, [](float x, float y) { return x != y; }); }
inline Mask4 operator&(Mask4 a, Mask4 b) { return {a.v & b.v}; }
inline Mask4 operator|(Mask4 a, Mask4 b) { return {a.v | b.v}; }
inline Mask4 operator~(Mask4 a) { return {~a.v & 0xfu}; }
inline unsigned bits(Mask4 m) { return m.v; }
inline Float4 greater_or_second(Float4 a, Float4 b) { return lanes_detail::each(a, b, [](float x, float y) { return x > y ? x : y; }); }
inline Float4 less_or_second(Float4 a, Float4 b) { return lanes_detail::each(a, b, [](float x, float y) { return x < y ? x : y; }); }
inline Float4 abs(Float4 a) { return lanes_detail::each(a, a, [](float x, float) { return std::fabs(x); }); }
#endif

}  // namespace lanes_sse or lanes_plain
}  // namespace rt
