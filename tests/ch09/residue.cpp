// EXERCISES 09.1 and 09.2: the walk's residue p mod M, kept up to date with no division.
#include "09_hashed_voxels/hashed_grid.hpp"
#include "common/random.hpp"
#include "tests/ch07/describe.hpp"

#include <limits>

using namespace rt;
using namespace rt::grader;

GRADED_TEST("residue_step: a step's residue keeps its sign and lies strictly between -M and M", "09.1", 3)
{
    struct Case {
        std::int32_t step;
        std::uint32_t M;
        std::int32_t expected;
    };
    for (const Case& c : std::vector<Case>{{1, 7, 1}, {-1, 7, -1}, {40, 7, 5}, {-40, 7, -5}, {49, 7, 0}, {-49, 7, 0},
                                           {1 << 20, 1000003, (1 << 20) - 1000003}, {-(1 << 30), 1000003, -(1 << 30) % 1000003},
                                           {5, 1, 0}}) {
        const std::int32_t got = residue_step(c.step, c.M);
        INFO("09.1 residue_step(" << c.step << ", M = " << c.M << "): got " << got << ", expected " << c.expected);
        CHECK(got == c.expected);
    }
}

GRADED_TEST("advance_residue: r + step brought back into [0, M) with one correction", "09.2", 3)
{
    struct Case {
        std::uint32_t r;
        std::int32_t step;
        std::uint32_t M;
        std::uint32_t expected;
    };
    for (const Case& c : std::vector<Case>{{3, 2, 7, 5}, {5, 2, 7, 0}, {6, 6, 7, 5}, {0, -1, 7, 6}, {2, -6, 7, 3},
                                           {0, 0, 7, 0}, {4294967290u, 4, 4294967291u, 3}, {0, 0, 1, 0}}) {
        const std::uint32_t got = advance_residue(c.r, c.step, c.M);
        INFO("09.2 advance_residue(r = " << c.r << ", step " << c.step << ", M = " << c.M << "): got " << got << ", expected "
             << c.expected);
        CHECK(got == c.expected);
    }
}

namespace {

constexpr std::int32_t int_max = std::numeric_limits<std::int32_t>::max();
constexpr std::int32_t int_min = std::numeric_limits<std::int32_t>::min();
constexpr std::uint32_t uint_max = std::numeric_limits<std::uint32_t>::max();

struct StepCase {
    std::int32_t step;
    std::uint32_t M;
    std::int32_t expected;
    const char* why;
};

void check_steps(const std::vector<StepCase>& cases)
{
    for (const StepCase& c : cases) {
        const std::int32_t got = residue_step(c.step, c.M);
        INFO("09.1 residue_step(" << c.step << ", M = " << c.M << "): got " << got << ", expected " << c.expected << ": "
             << c.why);
        CHECK(got == c.expected);
    }
}

struct AdvanceCase {
    std::uint32_t r;
    std::int32_t step;
    std::uint32_t M;
    std::uint32_t expected;
    const char* why;
};

void check_advances(const std::vector<AdvanceCase>& cases)
{
    for (const AdvanceCase& c : cases) {
        const std::uint32_t got = advance_residue(c.r, c.step, c.M);
        INFO("09.2 advance_residue(r = " << c.r << ", step " << c.step << ", M = " << c.M << "): got " << got
             << ", expected " << c.expected << ": " << c.why);
        CHECK(got == c.expected);
    }
}

}  // namespace

GRADED_TEST("residue_step: a step of exactly +-M gives 0, one less keeps all of it, one more leaves +-1", "09.1", 2)
{
    check_steps({{7, 7, 0, "step = M"},
                 {6, 7, 6, "step = M - 1: already strictly between -M and M"},
                 {8, 7, 1, "step = M + 1"},
                 {-7, 7, 0, "step = -M"},
                 {-6, 7, -6, "step = -(M - 1)"},
                 {-8, 7, -1, "step = -(M + 1): the sign of the step"}});
}

STABILITY_TEST("residue_step: any 32-bit unsigned M, up to 2^32 - 1, with steps up to the int's extremes", "09.1", 3)
{
    check_steps({{int_max, uint_max, int_max, "M = 2^32 - 1 is larger than any step: the step itself"},
                 {int_min, uint_max, int_min, "M = 2^32 - 1, step -2^31: the step itself"},
                 {-1, uint_max, -1, "M = 2^32 - 1, step -1"},
                 {1, uint_max, 1, "M = 2^32 - 1, step 1"},
                 {int_min, 2147483648u, 0, "M = 2^31, step -2^31 = -M: 0"},
                 {int_max, 2147483648u, int_max, "M = 2^31, step 2^31 - 1 = M - 1"},
                 {-int_max, 2147483648u, -int_max, "M = 2^31, step -(2^31 - 1)"},
                 {int_min, 2147483649u, int_min, "M = 2^31 + 1, step -2^31 = -(M - 1)"},
                 {int_max, 2147483647u, 0, "M = 2^31 - 1, step M"},
                 {int_min, 2147483647u, -1, "M = 2^31 - 1, step -2^31 = -(M + 1)"}});
}

GRADED_TEST("advance_residue: r + step exactly M gives 0, one less M - 1, one more 1; exactly 0 stays 0, -1 gives M - 1", "09.2", 2)
{
    check_advances({{5, 2, 7, 0, "5 + 2 = 7 = M: bucket 0"},
                    {5, 1, 7, 6, "5 + 1 = 6 = M - 1: no correction"},
                    {5, 3, 7, 1, "5 + 3 = 8 = M + 1: 1"},
                    {2, -2, 7, 0, "2 - 2 = 0: no correction"},
                    {2, -3, 7, 6, "2 - 3 = -1: M - 1"},
                    {6, -6, 7, 0, "6 - 6 = 0"}});
}

STABILITY_TEST("advance_residue: any 32-bit unsigned M, up to 2^32 - 1: sums past 2^31 - 1 and up to 2^33, below 0 down to -2^31", "09.2", 3)
{
    check_advances({{uint_max - 1, 1, uint_max, 0, "M = 2^32 - 1, r = M - 1, step 1: the sum is M, bucket 0"},
                    {uint_max - 1, -1, uint_max, uint_max - 2, "M = 2^32 - 1, r = M - 1, step -1"},
                    {0, -1, uint_max, uint_max - 1, "M = 2^32 - 1, r = 0, step -1: M - 1"},
                    {2147483647u, 1, uint_max, 2147483648u, "M = 2^32 - 1: r + step = 2^31, past any int, below M"},
                    {0, int_min, uint_max, 2147483647u, "M = 2^32 - 1, r = 0, step -2^31: M - 2^31"},
                    {uint_max - 1, int_max, uint_max, 2147483646u,
                     "M = 2^32 - 1, r = M - 1, step 2^31 - 1: the sum 2^32 + 2^31 - 3 is past M, and past 2^32"},
                    {2147483648u, int_max, uint_max, 0, "M = 2^32 - 1, r = 2^31, step 2^31 - 1: the sum is M"},
                    {2147483647u, 1, 2147483648u, 0, "M = 2^31, r = M - 1, step 1: the sum is M"},
                    {0, 5, 2147483648u, 5, "M = 2^31, r = 0, step 5: no correction"},
                    {2147483647u, int_max, 2147483648u, 2147483646u, "M = 2^31, r = step = M - 1: 2M - 2 - M"},
                    {0, -int_max, 2147483648u, 1, "M = 2^31, r = 0, step -(M - 1): 1"},
                    {2147483648u, 0, 2147483649u, 2147483648u, "M = 2^31 + 1, r = M - 1, step 0"}});
}

GRADED_TEST("the walk's residue stays p mod M over long seeded walks (M prime, a power of two, and tiny)", "09.2", 4)
{
    const GridShape g = grid_shape({{0, 0, 0}, {30, 20, 10}}, {300, 200, 100});
    Rng rng(9, 1);
    int wrong = 0, steps = 0;
    std::string first;
    for (const std::uint32_t M : {1000003u, 1u << 16, 7u, 1u}) {
        for (int k = 0; k < 200; ++k) {
            const point3 o(30 * rng.next_float(), 20 * rng.next_float(), 10 * rng.next_float());
            const vec3 d = glm::normalize(vec3(2 * rng.next_float() - 1, 2 * rng.next_float() - 1, 2 * rng.next_float() - 1));
            GridWalk w = start_walk(g, {o, d}, {0.0f, infinity});
            if (w.missed)
                continue;
            std::int32_t step_r[3];
            for (int a = 0; a < 3; ++a)
                step_r[a] = residue_step(w.step_p[a], M);
            std::uint32_t r = static_cast<std::uint32_t>(w.p) % M;
            for (;;) {
                const int before = w.p;
                if (!next_cell(w))
                    break;
                const int moved = w.p - before;
                const int a = moved == w.step_p[0] ? 0 : moved == w.step_p[1] ? 1 : 2;
                r = advance_residue(r, step_r[a], M);
                ++steps;
                if (r != static_cast<std::uint32_t>(w.p) % M && wrong++ == 0)
                    first = "M = " + std::to_string(M) + ", p = " + std::to_string(w.p) + ": residue " + std::to_string(r) +
                            ", p mod M = " + std::to_string(static_cast<std::uint32_t>(w.p) % M);
            }
        }
    }
    INFO("09.2 " << steps << " steps of walks through a 300 x 200 x 100 grid: " << wrong << " residues wrong; the first: " << first);
    CHECK(steps > 10000);
    CHECK(wrong == 0);
}
