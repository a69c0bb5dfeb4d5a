// A table that a lesson shows, written by the sweep that measures it, so that the lesson's numbers
// are the code's. Each program's --sweep writes its tables into NAME.tables.md beside its CSV;
// the `lesson_tables` target pastes each one into the lesson between `<!-- table NAME -->` and
// `<!-- end table -->`, and the test `lessons.tables_NN` fails when a lesson's cells differ from
// what the current code computes, in every column but the timed ones (which vary with the machine
// and its load: they carry their spread, and the caption says where and when they were measured).
#pragma once

#include "common/trade.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace rt {

struct LessonColumn {
    std::string header;
    bool timed = false;  // a time, or a ratio of times: not held to the code by the check
};

struct LessonTable {
    std::string name;  // chapter-qualified, e.g. "07.lambda"
    std::vector<LessonColumn> columns;
    std::vector<std::vector<std::string>> rows;
    std::string caption;  // how it was measured; "where and when" is added for a timed table

    LessonTable& row(std::vector<std::string> cells);
    bool timed() const;
};

// Numbers as a lesson shows them: fixed decimals, significant digits (trailing zeros kept, never
// an exponent), scientific ("2.07e-2"), an
// integer with thousands separators, and a time's spread (" ±3%": the farthest run from the median,
// as a share of it; empty for a single run or a computed time), as in fixed(t.median, 1) + spread(t).
std::string fixed(double v, int decimals);
std::string significant(double v, int digits);
std::string scientific(double v, int digits);
std::string grouped(unsigned long long v);
std::string spread(const Timing& t);

// The markdown block for one table: the marker, the table, the caption, the end marker.
void write_lesson_table(std::ostream& out, const LessonTable& table);

// Prints each table to `out` and writes all of them to `path` (throws InputError naming the path
// when it cannot be written).
void write_lesson_tables(const std::string& path, const std::vector<LessonTable>& tables, std::ostream& out);

// A chapter's trade table as its lesson shows it: the knob's value, seconds with their spread,
// rays, rays per second when asked, and the error (3 significant digits).
LessonTable trade_lesson_table(const std::string& name, const TradeTable& table, const std::string& knob_header,
                               const std::string& error_header, bool with_rays_per_second, const std::string& caption);

// Where a sweep writing `csv` puts its lesson tables: "out/07_uniform_grid.csv" gives
// "out/07_uniform_grid.tables.md".
std::string tables_beside(const std::string& csv);

}  // namespace rt
