// What a case measured beside its verdict, for the class leaderboard (10.7's cost against the
// reference's): the case reports it, and the grader's listener copies it into the case's result
// (points.hpp's CaseResult::measure) when the case ends. Lower ranks first.
#pragma once

#include <optional>
#include <string>

namespace rt::grader {

struct Measure {
    std::string name;        // what is measured, the leaderboard's column: "10.7 cost"
    double value = 0.0;      // the student's
    double reference = 0.0;  // the reference solution's, for the student's own summary
    std::string detail;      // how it was reached, a line a scene, for the grader's console only
};

// The measure of the case running now, if it reported one.
inline std::optional<Measure> measured_now;

inline void report_measure(const std::string& name, double value, double reference, const std::string& detail = "")
{
    measured_now = Measure{name, value, reference, detail};
}

}  // namespace rt::grader
