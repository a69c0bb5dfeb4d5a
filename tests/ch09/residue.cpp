// EXERCISES 09.1 and 09.2: the walk's residue p mod M, kept up to date with no division.
#include "09_hashed_voxels/hashed_grid.hpp"
#include "common/random.hpp"
#include "tests/ch07/describe.hpp"

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
        INFO("residue_step(" << c.step << ", M = " << c.M << "): got " << got << ", expected " << c.expected);
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
        INFO("advance_residue(r = " << c.r << ", step " << c.step << ", M = " << c.M << "): got " << got << ", expected "
             << c.expected);
        CHECK(got == c.expected);
    }
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
    INFO(steps << " steps of walks through a 300 x 200 x 100 grid: " << wrong << " residues wrong; the first: " << first);
    CHECK(steps > 10000);
    CHECK(wrong == 0);
}
