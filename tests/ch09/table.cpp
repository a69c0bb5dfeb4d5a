// EXERCISES 09.3 and 09.4: the occupancy bits, and finding a cell in its bucket among the others
// that share its residue.
#include "09_hashed_voxels/hashed_grid.hpp"
#include "tests/ch07/describe.hpp"

using namespace rt;
using namespace rt::grader;

GRADED_TEST("occupied: bit p of the array, word p / 64, bit p % 64", "09.3", 3)
{
    OccupancyBits bits;
    bits.words.assign(4, 0);
    for (const int p : {0, 63, 64, 130, 255})
        bits.words[static_cast<size_t>(p) / 64] |= std::uint64_t{1} << (p % 64);
    for (int p = 0; p < 256; ++p) {
        const bool expected = p == 0 || p == 63 || p == 64 || p == 130 || p == 255;
        INFO("09.3 occupied(bits with cells 0, 63, 64, 130 and 255 set, " << p << "): got " << std::boolalpha
             << occupied(bits, p) << ", expected " << expected);
        CHECK(occupied(bits, p) == expected);
    }
}

namespace {

// A table of M = 5 buckets holding cells 3, 8 and 13 (all in bucket 3) and 7 (bucket 2).
HashTable colliding()
{
    HashTable t;
    t.M = 5;
    t.bucket_start = {0, 0, 0, 1, 4, 4};
    t.cells = {{7, 0, 1}, {3, 1, 1}, {8, 2, 2}, {13, 4, 1}};
    t.object_index = {10, 11, 12, 13, 14};
    return t;
}

}  // namespace

GRADED_TEST("find_cell: the cell whose key matches, among the cells that share its bucket", "09.4", 4)
{
    const HashTable t = colliding();
    for (const std::int32_t p : {3, 8, 13, 7}) {
        const HashedCell* c = find_cell(t, p, static_cast<std::uint32_t>(p) % t.M);
        INFO("09.4 find_cell(cells 3, 8, 13 in bucket 3 of M = 5, cell 7 in bucket 2; p = " << p << "): got "
             << (c ? "the cell with key " + std::to_string(c->p) : std::string("nothing")) << ", expected the cell " << p);
        REQUIRE(c);
        CHECK(c->p == p);
    }
    for (const std::int32_t p : {18, 2, 0}) {
        const HashedCell* c = find_cell(t, p, static_cast<std::uint32_t>(p) % t.M);
        INFO("09.4 find_cell(p = " << p << ", which the table does not hold; bucket " << p % 5 << "): got "
             << (c ? "the cell with key " + std::to_string(c->p) : std::string("nothing")) << ", expected nothing: "
             << (p == 18  ? "cell 18 shares bucket 3 with 3, 8 and 13, but is none of them"
                 : p == 2 ? "cell 2 shares bucket 2 with cell 7, but is not it"
                          : "an empty bucket"));
        CHECK(c == nullptr);
    }
}

GRADED_TEST("the hashed grid's table keeps colliding cells apart: a table of 1 to 7 buckets answers as 2^20 do", "09.4", 4)
{
    const std::vector<Sphere> spheres = {{{0, 0, 0}, 0.4f}, {{3, 0, 0}, 0.4f}, {{0, 3, 0}, 0.4f}, {{1.5f, 1.5f, 3}, 0.6f}};
    Objects o;
    o.spheres = spheres.data();
    o.sphere_count = 4;
    const HashedGrid roomy(o, 64.0f, 1u << 20);
    int wrong = 0, rays = 0, hits = 0;
    for (const std::uint32_t M : {1u, 2u, 3u, 7u}) {
        const HashedGrid tight(o, 64.0f, M);
        for (int i = 0; i < 30; ++i)
            for (int j = 0; j < 30; ++j) {
                const Ray ray{{-1 + 0.17f * i, -1 + 0.17f * j, -5}, glm::normalize(vec3(0.05f, 0.02f, 1))};
                ObjectHit a, b;
                const bool fa = roomy.closest(ray, {0.0f, infinity}, o, a);
                const bool fb = tight.closest(ray, {0.0f, infinity}, o, b);
                ++rays;
                hits += fb;
                wrong += fa != fb || (fa && (a.object != b.object || a.t != b.t));
            }
        INFO("09.4 table size " << M << ": " << tight.stats().collisions << " collisions among " << tight.stats().occupied
             << " occupied cells");
        CHECK(tight.stats().collisions > 0);
    }
    INFO("09.4 " << wrong << " of " << rays << " rays answered differently with a table of 1 to 7 buckets than with 2^20; "
         << hits << " of them hit a sphere");
    CHECK(wrong == 0);
    CHECK(hits >= rays / 20);
}

GRADED_TEST("occupied: far into a large array, past 2^26 cells: the bit and its neighbours in the last word", "09.3", 2)
{
    // 2^20 + 1 words (8 MB), the last holding cells 2^26 to 2^26 + 63; bits 2^26 - 1 (the end of
    // the word before), 2^26 + 1 and 2^26 + 63 (the array's last cell) are set.
    OccupancyBits bits;
    bits.words.assign((std::size_t{1} << 20) + 1, 0);
    const std::int32_t base = 1 << 26;
    const std::int32_t set[] = {base - 1, base + 1, base + 63};
    for (const std::int32_t p : set)
        bits.words[static_cast<std::size_t>(p) / 64] |= std::uint64_t{1} << (p % 64);
    for (std::int32_t p = base - 2; p <= base + 63; ++p) {
        const bool expected = p == set[0] || p == set[1] || p == set[2];
        const bool got = occupied(bits, p);
        INFO("09.3 occupied(bits with cells 2^26 - 1, 2^26 + 1 and 2^26 + 63 set, " << p << " = 2^26 + " << p - base
             << "): got " << std::boolalpha << got << ", expected " << expected);
        CHECK(got == expected);
    }
}

namespace {

// A table of M = 5 buckets whose last bucket (4) holds cells 4 and 9, after cell 3 in bucket 3.
HashTable last_bucket()
{
    HashTable t;
    t.M = 5;
    t.bucket_start = {0, 0, 0, 0, 1, 3};
    t.cells = {{3, 0, 1}, {4, 1, 2}, {9, 3, 1}};
    t.object_index = {10, 11, 12, 13};
    return t;
}

}  // namespace

GRADED_TEST("find_cell: returns the table's own cell, in place (first and count too), in the last bucket as in the others", "09.4", 2)
{
    for (const HashTable& t : {colliding(), last_bucket()}) {
        for (std::size_t k = 0; k < t.cells.size(); ++k) {
            const HashedCell& own = t.cells[k];
            const HashedCell* c = find_cell(t, own.p, static_cast<std::uint32_t>(own.p) % t.M);
            INFO("09.4 find_cell(p = " << own.p << ", bucket " << own.p % 5 << " of M = 5, the table's cell " << k
                 << " holding objects " << own.first << " .. " << own.first + own.count << "): got "
                 << (c ? "a cell with key " + std::to_string(c->p) + ", first " + std::to_string(c->first) + ", count " +
                             std::to_string(c->count) + (c == &own ? ", the table's own" : ", not the table's own (a copy?)")
                       : std::string("nothing"))
                 << "; expected the table's own cell " << k << (own.p % 5 == 4 ? " (bucket 4 is the last)" : ""));
            REQUIRE(c);
            CHECK(c == &own);
        }
    }
    const HashTable t = last_bucket();
    const HashedCell* c = find_cell(t, 14, 4);
    INFO("09.4 find_cell(p = 14, the last bucket 4, which holds cells 4 and 9 only): got "
         << (c ? "the cell with key " + std::to_string(c->p) : std::string("nothing")) << ", expected nothing");
    CHECK(c == nullptr);
}
