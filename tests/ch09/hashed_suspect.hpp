// Chapter 09's diagnosis of one ray the hashed grid answers differently from brute force
// (tests/ch07/suspect.hpp): the query replayed on that ray along chapter 07's walk, each exercise
// held to its own contract, in the order the query uses them:
//  - when the walk starts, each axis's step residue (09.1): congruent to step_p modulo M, of its
//    sign, strictly between -M and M (exactly one number is);
//  - in each cell: its occupancy bit (09.3) as the table's cells set it; with the bit on, its cell
//    in the table (09.4): the table's own cell of key p in bucket p mod M, or nullptr when the
//    bucket holds none; the cell's query (09.5): chapter 07's cell query over that cell's list,
//    one lookup or one skipped lookup counted;
//  - at each step, the residue carried along (09.2): p mod M of the cell entered.
#pragma once

#include "09_hashed_voxels/hashed_grid.hpp"
#include "tests/ch07/grid_suspect.hpp"

namespace rt::grader::suspect {

// The table's cell of key p, found by reading its bucket (09.4's promise).
inline const HashedCell* cell_in_table(const HashTable& table, std::int32_t p)
{
    const std::uint32_t r = static_cast<std::uint32_t>(p) % table.M;
    for (std::uint32_t i = table.bucket_start[r]; i < table.bucket_start[r + 1]; ++i)
        if (table.cells[i].p == p)
            return &table.cells[i];
    return nullptr;
}

inline std::string show_cell(const HashTable& table, const HashedCell* c)
{
    if (!c)
        return "nullptr";
    if (c < table.cells.data() || c >= table.cells.data() + table.cells.size())
        return "a pointer outside the table's cells";
    return "the table's cell of key " + std::to_string(c->p) + " (" + std::to_string(c->count) + " objects)";
}

inline std::string diagnose_hashed(const HashedGrid& grid, const Ray& ray, Interval range, const Objects& objects)
{
    Diagnosis d;
    d.exercised = "09.1-09.5 (with chapter 07's walk and the given build)";
    const HashTable& table = grid.table();
    const GridShape& shape = grid.shape();
    const std::uint32_t M = table.M;
    // The occupancy bits as the build sets them: one for each cell the table holds.
    OccupancyBits bits;
    bits.words.assign((static_cast<std::size_t>(shape.cell_count()) + 63) / 64, 0);
    for (const HashedCell& c : table.cells)
        bits.words[static_cast<std::uint32_t>(c.p) >> 6] |= std::uint64_t{1} << (static_cast<std::uint32_t>(c.p) & 63u);
    GridWalk w = start_walk(shape, ray, range);
    if (w.missed) {
        d.check("09.1", "residue_step");
        return d.text();
    }
    std::int32_t step[3];
    for (int a = 0; a < 3; ++a) {
        d.check("09.1", "residue_step");
        const std::int32_t got = residue_step(w.step_p[a], M);
        step[a] = static_cast<std::int32_t>(static_cast<std::int64_t>(w.step_p[a]) % static_cast<std::int64_t>(M));
        if (got != step[a]) {
            d.fail("09.1", "residue_step", "for the walk's step_p " + std::to_string(w.step_p[a]) + " (axis " + std::to_string(a) + ") and M = " + std::to_string(M) +
                                               " it returned " + std::to_string(got) + "; its contract promises " + std::to_string(step[a]) +
                                               " (congruent to step_p modulo M, of its sign, strictly between -M and M)");
            return d.text();
        }
    }
    std::uint32_t r = static_cast<std::uint32_t>(w.p) % M;
    ObjectHit best;
    for (;;) {
        d.check("09.3", "occupied");
        const bool bit = (bits.words[static_cast<std::uint32_t>(w.p) >> 6] >> (static_cast<std::uint32_t>(w.p) & 63u)) & 1u;
        if (occupied(bits, w.p) != bit) {
            d.fail("09.3", "occupied", "for cell p = " + std::to_string(w.p) + " (word " + std::to_string(w.p >> 6) + ", bit " + std::to_string(w.p & 63) + ") it answered " +
                                           (bit ? "false" : "true") + "; its contract promises " + (bit ? "true: the table holds the cell" : "false: its bit is off"));
            return d.text();
        }
        const HashedCell* cell = bit ? cell_in_table(table, w.p) : nullptr;
        if (bit) {
            d.check("09.4", "find_cell");
            const HashedCell* got = find_cell(table, w.p, r);
            if (got != cell) {
                d.fail("09.4", "find_cell", "for p = " + std::to_string(w.p) + " in bucket " + std::to_string(r) + " (M = " + std::to_string(M) + ", " +
                                                std::to_string(table.bucket_start[r + 1] - table.bucket_start[r]) + " cells in the bucket) it returned " + show_cell(table, got) +
                                                "; its contract promises " + show_cell(table, cell) + " (the cell whose key is p, never a neighbour's)");
                return d.text();
            }
        }
        d.check("09.5", "closest_in_hashed_cell");
        std::vector<std::uint32_t> list;
        if (cell)
            list.assign(table.object_index.begin() + cell->first, table.object_index.begin() + cell->first + cell->count);
        ObjectHit got_best = best, want_best = best;
        const std::uint64_t lookups0 = counted(local_counts(), Counter::table_lookups);
        const std::uint64_t skipped0 = counted(local_counts(), Counter::table_lookups_skipped);
        const bool got = closest_in_hashed_cell(table, bits, w, r, ray, range, objects, got_best);
        const std::uint64_t lookups = counted(local_counts(), Counter::table_lookups) - lookups0;
        const std::uint64_t skipped = counted(local_counts(), Counter::table_lookups_skipped) - skipped0;
        const bool want = cell_query_promised(list, ray, range, w.cell_exit(), objects, want_best);
        const std::string differs = cell_differs(got, got_best, want, want_best, w, best, list.size());
        if (!differs.empty()) {
            d.fail("09.5", "closest_in_hashed_cell", differs);
            return d.text();
        }
        if (lookups != (bit ? 1u : 0u) || skipped != (bit ? 0u : 1u)) {
            d.fail("09.5", "closest_in_hashed_cell", "in cell p = " + std::to_string(w.p) + ", its bit " + (bit ? "on" : "off") + ", it counted " + std::to_string(lookups) +
                                                         " table lookups and " + std::to_string(skipped) + " skipped; its contract promises " +
                                                         (bit ? "one lookup" : "one skipped lookup and no table access: the bit is the authority"));
            return d.text();
        }
        best = want_best;
        if (want)
            break;
        const int before = w.p;
        if (!next_cell(w))
            break;
        const int moved = w.p - before;
        const int a = moved == w.step_p[0] ? 0 : moved == w.step_p[1] ? 1 : 2;
        d.check("09.2", "advance_residue");
        const std::uint32_t next = advance_residue(r, step[a], M);
        const std::uint32_t want_r = static_cast<std::uint32_t>(w.p) % M;
        if (next != want_r) {
            d.fail("09.2", "advance_residue", "stepping from p = " + std::to_string(before) + " (residue " + std::to_string(r) + ") to p = " + std::to_string(w.p) + " with step " +
                                                  std::to_string(step[a]) + ", M = " + std::to_string(M) + ", it returned " + std::to_string(next) +
                                                  "; its contract promises " + std::to_string(want_r) + " (p mod M, in [0, M))");
            return d.text();
        }
        r = next;
    }
    return d.text();
}

}  // namespace rt::grader::suspect
