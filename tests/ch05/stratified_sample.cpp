// EXERCISE 05.3: stratified (jittered) samples: one uniform point in each cell of an n x n grid.
#include "tests/ch05/describe.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

using namespace rt;
using namespace rt::grader;

namespace {

// Which cell of the n x n grid a coordinate lies in, or -1 outside [0, 1).
int cell_of(float x, int n)
{
    if (!(x >= 0.0f && x < 1.0f))
        return -1;
    return std::min(n - 1, static_cast<int>(static_cast<double>(x) * n));
}

std::uint32_t bits_of(float x)
{
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

// A float and its bit pattern, for the clamp's failures.
std::string show_bits(float x)
{
    std::ostringstream s;
    s.precision(9);
    s << x << " (bits 0x" << std::hex << bits_of(x) << ')';
    return s.str();
}

}  // namespace

GRADED_TEST("stratified_sample: sample k of an n x n grid lies in column k mod n, row k div n, inside [0, 1)^2", "05.3", 3)
{
    Rng rng(57, 0);
    for (const int n : {1, 2, 3, 4, 7, 16}) {
        for (int round = 0; round < 20; ++round)
            for (int k = 0; k < n * n; ++k) {
                const sample2 u = stratified_sample(k, n, rng);
                INFO("stratified_sample(k = " << k << ", n = " << n << ") gave " << show(u) << ", in column "
                     << cell_of(u.x, n) << " and row " << cell_of(u.y, n) << " (-1: outside [0, 1)); expected column "
                     << k % n << " = k mod n, row " << k / n << " = k div n: x in [" << k % n << "/" << n << ", "
                     << k % n + 1 << "/" << n << "), y in [" << k / n << "/" << n << ", " << k / n + 1 << "/" << n
                     << ")");
                REQUIRE(cell_of(u.x, n) == k % n);
                REQUIRE(cell_of(u.y, n) == k / n);
            }
    }
}

GRADED_TEST("stratified_sample: the jitter is uniform over the cell, fresh from the stream every call, x drawn before y", "05.3", 2)
{
    // Offsets within the cell, in cell units: uniform on [0, 1) has mean 1/2 and variance 1/12.
    // The cell's centre (no jitter), the same offset for every cell, or a stream not advanced
    // fail this.
    constexpr int n = 4, rounds = 2000;
    constexpr double count = static_cast<double>(n * n * rounds);
    Rng rng(58, 0);
    double sum_x = 0.0, sum_xx = 0.0, sum_y = 0.0, sum_yy = 0.0;
    int repeats = 0;
    double previous_ox = -1.0;
    for (int round = 0; round < rounds; ++round)
        for (int k = 0; k < n * n; ++k) {
            const sample2 u = stratified_sample(k, n, rng);
            const double ox = u.x * n - k % n, oy = u.y * n - k / n;
            sum_x += ox;
            sum_xx += ox * ox;
            sum_y += oy;
            sum_yy += oy * oy;
            repeats += std::abs(ox - previous_ox) < 1e-6;
            previous_ox = ox;
        }
    const double mean_x = sum_x / count, mean_y = sum_y / count;
    const double var_x = sum_xx / count - mean_x * mean_x, var_y = sum_yy / count - mean_y * mean_y;
    // Standard errors: of the mean sqrt(1/12 / count), of the variance sqrt(1/180 / count) (the
    // uniform distribution's fourth central moment is 1/80); 5 of each.
    const double mean_tolerance = 5.0 * std::sqrt(1.0 / 12.0 / count);
    const double var_tolerance = 5.0 * std::sqrt(1.0 / 180.0 / count);
    INFO(rounds << " rounds of the 16 samples of a 4 x 4 grid: the offsets within their cells (in cell units) have "
         << "mean (" << mean_x << ", " << mean_y << ") and variance (" << var_x << ", " << var_y
         << "); expected 0.5 within " << mean_tolerance << " and 1/12 = 0.0833 within " << var_tolerance
         << " (a uniform point in each cell, from two fresh numbers of the stream); " << repeats
         << " samples repeated the previous sample's x offset");
    CHECK(std::abs(mean_x - 0.5) <= mean_tolerance);
    CHECK(std::abs(mean_y - 0.5) <= mean_tolerance);
    CHECK(std::abs(var_x - 1.0 / 12.0) <= var_tolerance);
    CHECK(std::abs(var_y - 1.0 / 12.0) <= var_tolerance);
    CHECK(repeats < 10);

    // The contract's order: x from the first number drawn, y from the second.
    Rng a(59, 3), b(59, 3);
    for (int k = 0; k < 9; ++k) {
        const sample2 u = stratified_sample(k, 3, a);
        const float xi_x = b.next_float(), xi_y = b.next_float();
        const sample2 want{(static_cast<float>(k % 3) + xi_x) / 3.0f, (static_cast<float>(k / 3) + xi_y) / 3.0f};
        INFO("stratified_sample(k = " << k << ", n = 3) gave " << show(u) << "; with the stream's next two numbers "
             << xi_x << " and " << xi_y << ", expected ((a + " << xi_x << ") / 3, (b + " << xi_y << ") / 3) = "
             << show(want));
        CHECK(std::abs(u.x - want.x) <= 1e-6f);
        CHECK(std::abs(u.y - want.y) <= 1e-6f);
    }
}

GRADED_TEST("stratified_sample: 16 stratified points estimate a smooth integral with under half the variance of 16 random ones", "05.3", 2)
{
    // f(x, y) = 1 / (1 + (2x - 1)^2 + (2y - 1)^2)^2 is the light a 2 x 2 square light 1 above a
    // point sends onto it (cos cos / d^2), a smooth function of the square. Stratification removes
    // the variance between cells, which for a smooth f is most of it (pbrt-v4, "Stratified
    // Sampling"): here about a quarter remains at 16 samples, less at more; random sampling keeps
    // it all.
    const auto f = [](sample2 u) {
        const double x = 2.0 * u.x - 1.0, y = 2.0 * u.y - 1.0, d = 1.0 + x * x + y * y;
        return 1.0 / (d * d);
    };
    constexpr int n = 4, estimates = 4000;
    Rng stratified_rng(60, 0), random_rng(60, 1);
    double s = 0.0, ss = 0.0, r = 0.0, rr = 0.0;
    for (int e = 0; e < estimates; ++e) {
        double strat = 0.0, rand = 0.0;
        for (int k = 0; k < n * n; ++k) {
            strat += f(stratified_sample(k, n, stratified_rng));
            const float x = random_rng.next_float(), y = random_rng.next_float();
            rand += f({x, y});
        }
        strat /= n * n;
        rand /= n * n;
        s += strat;
        ss += strat * strat;
        r += rand;
        rr += rand * rand;
    }
    const double var_stratified = ss / estimates - (s / estimates) * (s / estimates);
    const double var_random = rr / estimates - (r / estimates) * (r / estimates);
    INFO(estimates << " estimates of a smooth integral over the square (exact value 0.43521) with 16 samples each: "
         << "stratified mean " << s / estimates << ", variance " << var_stratified << "; random mean " << r / estimates
         << ", variance " << var_random << "; expected the stratified variance below half the random one "
         << "(ratio " << var_stratified / var_random << ") and both means within 0.002 of 0.43521");
    CHECK(var_stratified < 0.5 * var_random);
    CHECK(std::abs(s / estimates - 0.43521) < 0.002);
}

STABILITY_TEST("stratified_sample: never 1, even in the last cell of a 256 x 256 or 4096 x 4096 grid with the jitter near 1", "05.3", 1)
{
    // (n - 1 + xi) / n rounds to 1 when xi lies within a float step of 1: for n = 4096 about once in
    // 8000 draws, for 256 once in 130000. Clamped to one_minus_epsilon it stays in [0, 1).
    Rng rng(61, 0);
    for (const int n : {256, 4096}) {
        const int last = n * n - 1;
        for (int k = 0; k < 300000; ++k) {
            const sample2 u = stratified_sample(last, n, rng);
            INFO("stratified_sample(k = " << last << ", n = " << n << ") gave " << show(u)
                 << "; expected both coordinates below 1 (at most one_minus_epsilon) and in the last cell");
            REQUIRE(u.x < 1.0f);
            REQUIRE(u.y < 1.0f);
            REQUIRE(u.x >= static_cast<float>(n - 1) / static_cast<float>(n));
        }
    }
}

GRADED_TEST("stratified_sample: a coordinate that rounds to 1 comes back as exactly one_minus_epsilon, one that rounds just below 1 is kept; two numbers a call", "05.3", 1)
{
    // In the last cell of a 4096 x 4096 grid, (4095 + xi) / 4096 rounds to 1 when xi is within
    // 2^-13 of 1, and to one_minus_epsilon (1 - 2^-24) a step below that. The contract clamps to
    // at most one_minus_epsilon, the largest float below 1: the first must come back as exactly
    // that, the second unchanged (not 1 - FLT_EPSILON = 1 - 2^-23, two steps below 1). With n a
    // power of two every way of writing the formula rounds to the same float, so each call is
    // compared bit for bit, its numbers taken from a copy of the stream, two a call.
    constexpr int n = 4096, last = n * n - 1;
    const auto formula = [](float xi) {
        return std::min((static_cast<float>(n - 1) + xi) / static_cast<float>(n), one_minus_epsilon);
    };
    Rng rng(62, 0), copy(62, 0);
    int rounds_to_one[2] = {0, 0}, just_below[2] = {0, 0};
    int call = 0;
    for (; call < 1000000 && !(rounds_to_one[0] && rounds_to_one[1] && just_below[0] && just_below[1]); ++call) {
        const float xi[2] = {copy.next_float(), copy.next_float()};
        const sample2 u = stratified_sample(last, n, rng);
        const float got[2] = {u.x, u.y};
        for (int c = 0; c < 2; ++c) {
            const float unclamped = (static_cast<float>(n - 1) + xi[c]) / static_cast<float>(n);
            rounds_to_one[c] += unclamped == 1.0f;
            just_below[c] += unclamped == one_minus_epsilon;
            INFO("call " << call << ": stratified_sample(k = " << last << ", n = " << n << ") gave " << show(u)
                 << "; its " << (c == 0 ? "x" : "y") << " number (the stream's " << (c == 0 ? "first" : "second")
                 << " of the call) is xi = " << xi[c] << ", so (4095 + xi) / 4096 = " << show_bits(unclamped)
                 << (unclamped == 1.0f ? ", which is 1 and clamps to one_minus_epsilon" : "") << "; expected "
                 << show_bits(formula(xi[c])) << ", got " << show_bits(got[c]));
            REQUIRE(bits_of(got[c]) == bits_of(formula(xi[c])));
        }
    }
    INFO("after " << call << " calls the stream and a copy that drew two numbers a call disagree: stratified_sample "
         "must draw exactly two numbers from rng per call");
    CHECK(rng.next_u32() == copy.next_u32());
    INFO("the seeded stream's " << call << " calls held x rounding to 1 " << rounds_to_one[0] << " times, y "
         << rounds_to_one[1] << ", x just below 1 " << just_below[0] << ", y " << just_below[1]);
    REQUIRE((rounds_to_one[0] && rounds_to_one[1] && just_below[0] && just_below[1]));
}
