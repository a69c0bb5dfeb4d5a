// next_up and next_down (common/interval.hpp), the kit's own std::nextafter toward infinity and
// toward -infinity: the same float for every x, at the edges where a bit trick breaks (zeros of both signs, the denormals, the largest float,
// the infinities, NaN) and on every sign and exponent by seeded random bits.
#include "common/interval.hpp"
#include "common/random.hpp"
#include "tests/grader/graded.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

using namespace rt;

namespace {

bool same_float(float a, float b)
{
    return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b));
}

void check_next_up(float x)
{
    INFO("x = " << std::hexfloat << x << ": next_up " << next_up(x) << ", std::nextafter "
                << std::nextafter(x, infinity));
    CHECK(same_float(next_up(x), std::nextafter(x, infinity)));
    INFO("next_down " << next_down(x) << ", std::nextafter " << std::nextafter(x, -infinity));
    CHECK(same_float(next_down(x), std::nextafter(x, -infinity)));
}

}  // namespace

TEST_CASE("next_up and next_down are std::nextafter toward either infinity at the edges of float")
{
    using lim = std::numeric_limits<float>;
    for (float x : {0.0f, -0.0f, lim::denorm_min(), -lim::denorm_min(), lim::min(), -lim::min(), lim::max(),
                    -lim::max(), lim::infinity(), -lim::infinity(), lim::quiet_NaN(), 1.0f, -1.0f})
        check_next_up(x);
}

TEST_CASE("next_up and next_down are std::nextafter toward either infinity on random bits of every sign and exponent")
{
    Rng rng(20261207, 1);
    for (int i = 0; i < 100000; ++i) {
        const std::uint32_t bits = rng.next_u32();
        float x;
        std::memcpy(&x, &bits, sizeof x);
        check_next_up(x);
    }
}
