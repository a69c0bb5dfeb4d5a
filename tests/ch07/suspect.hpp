// What a failing agreement case (chapters 07-10) says about the first ray that differs: each of the
// chapter's exercises the query uses, run again on that one ray and held to its own promise (its
// contract in chapters/NN_name/NN_name.hpp), in the order the query uses them; the first whose
// promise fails is named, with what it returned, what its contract promises and the hint to open.
// When every promise checked holds, the diagnosis names the exercises the case exercises and
// sends the student to their own cases. The chapters' diagnoses (grid_suspect.hpp here, and
// beside the agreement cases of chapters 08-10) build on this.
#pragma once

#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace rt::grader::suspect {

struct Diagnosis {
    std::string exercised;             // what the case exercises ("07.1-07.6")
    std::string subject = "that ray";  // what the exercises are run again on
    std::vector<std::string> checked;  // each exercise checked on the ray, in order ("07.4 start_walk")
    struct Finding {
        std::string exercise, function, what;  // what: what it returned, and what its contract promises
    };
    std::optional<Finding> found;

    // Records that `exercise`'s `function` was checked on the ray (once, in order).
    void check(const std::string& exercise, const std::string& function)
    {
        const std::string name = exercise + ' ' + function;
        for (const std::string& c : checked)
            if (c == name)
                return;
        checked.push_back(name);
    }
    // The first broken promise found: the likeliest exercise. Later ones are not kept.
    void fail(const std::string& exercise, const std::string& function, const std::string& what)
    {
        check(exercise, function);
        if (!found)
            found = Finding{exercise, function, what};
    }
    bool failed() const { return found.has_value(); }

    // At most four lines, each starting on a new line.
    std::string text() const
    {
        std::ostringstream s;
        s << "\nthe exercises run again on " << subject << ", each held to its own contract, in the order the query uses them (";
        for (size_t k = 0; k < checked.size(); ++k)
            s << (k ? ", " : "") << checked[k];
        s << "):";
        if (found) {
            s << "\n  likeliest " << found->exercise << ' ' << found->function << ": " << found->what;
            s << "\n  see " << found->exercise << ", hint " << found->exercise << " 2, the trap (./build/grade/hint "
              << found->exercise << " 2; tier 1, the idea, without the 2), and its own cases, tagged [" << found->exercise << "]";
        } else {
            s << "\n  each keeps its promise on " << subject << "; the case exercises " << exercised
              << ": start with their own cases (tagged [NN.k]) and the one that fails there";
        }
        return s.str();
    }
};

}  // namespace rt::grader::suspect
