// What a failing agreement case (chapters 07-10) says about the first ray that differs: each of the
// chapter's exercises the query uses, run again on that one ray and held to its own promise (its
// contract in chapters/NN_name/NN_name.hpp), in the order the query uses them; the first whose
// promise fails is named, with what it returned, what its contract promises and the hint to open.
// When every promise checked holds, the diagnosis names the exercises the case exercises and
// sends the student to their own cases. The chapters' diagnoses (grid_suspect.hpp here, and
// beside the agreement cases of chapters 08-10) build on this.
#pragma once

#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#ifndef _WIN32
#include <csetjmp>
#include <csignal>
#include <pthread.h>
#endif

namespace rt::grader::suspect {

// The exercise a diagnosis asked last ("07.6 closest_in_cell"), and the hint line for an exercise.
inline std::string asked_last;
inline std::string see(const std::string& exercise)
{
    return "\n  see " + exercise + ", hint " + exercise + " 2, the trap (./build/grade/hint " + exercise +
           " 2; tier 1, the idea, without the 2), and its own cases, tagged [" + exercise + "]";
}

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
        asked_last = name;
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
            s << see(found->exercise);
        } else {
            s << "\n  each keeps its promise on " << subject << "; the case exercises " << exercised
              << ": start with their own cases (tagged [NN.k]) and the one that fails there";
        }
        return s.str();
    }
};

#ifndef _WIN32
inline sigjmp_buf* guard_jump = nullptr;
inline void guard_handler(int) { siglongjmp(*guard_jump, 1); }
#endif

// Runs a diagnosis where a crash may happen again: while the grader reports a crash in a query,
// the diagnosis asks the same code, and a second crash there would end the process before the
// first is reported. On POSIX a crash inside is caught, and said, instead.
inline std::string guarded(const std::function<std::string()>& diagnose)
{
#ifdef _WIN32
    return diagnose();
#else
    // SIGABRT too: the student's file keeps GLM's index assertions, and abort() ends in it.
    constexpr int signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
    constexpr int count = sizeof signals / sizeof signals[0];
    struct sigaction act = {};
    struct sigaction old[count];
    act.sa_handler = guard_handler;
    sigemptyset(&act.sa_mask);
    act.sa_flags = SA_ONSTACK | SA_NODEFER;
    sigset_t unblock, before;
    sigemptyset(&unblock);
    for (int i = 0; i < count; ++i) {
        sigaction(signals[i], &act, &old[i]);
        sigaddset(&unblock, signals[i]);
    }
    sigjmp_buf jump;
    sigjmp_buf* const outer = guard_jump;
    guard_jump = &jump;
    pthread_sigmask(SIG_UNBLOCK, &unblock, &before);  // a crash's report runs with its signal blocked
    std::string text;
    asked_last.clear();
    if (sigsetjmp(jump, 0) == 0)
        text = diagnose();
    else if (asked_last.empty())
        text = "\nthe exercises run again on that ray crashed again: start with their own cases";
    else  // the crash came while the diagnosis was asking that exercise
        text = "\nthe exercises run again on that ray, each held to its own contract, crashed again:\n  likeliest " + asked_last +
               ": it crashed when asked again on that ray" + see(asked_last.substr(0, asked_last.find(' ')));
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    guard_jump = outer;
    for (int i = 0; i < count; ++i)
        sigaction(signals[i], &old[i], nullptr);
    return text;
#endif
}

}  // namespace rt::grader::suspect
