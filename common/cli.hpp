// The programs' small command line: `--name value` options and `--name` flags, checked as they are
// read. Anything wrong (an unknown flag, a missing or malformed value, a value out of range) throws
// InputError with one line naming the flag and the problem; run_program turns it into exit status 2.
#pragma once

#include "common/error.hpp"
#include "common/render.hpp"
#include "common/stats.hpp"

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace rt {

class CommandLine {
public:
    CommandLine(std::string program, std::string summary);

    void flag(const std::string& name, bool& target, const std::string& help);
    // Whole numbers in [min, max].
    void option(const std::string& name, int& target, const std::string& help, int min, int max);
    void option(const std::string& name, std::uint64_t& target, const std::string& help);
    // Finite numbers in the open interval (above, below).
    void option(const std::string& name, float& target, const std::string& help, float above, float below);
    void option(const std::string& name, std::string& target, const std::string& help);

    // Returns false when --help was asked for (the usage is then printed to `out`).
    bool parse(int argc, const char* const* argv, std::ostream& out);
    void print_usage(std::ostream& out) const;

    // Whether the last parse met the option `name`: a program whose default comes from elsewhere
    // (a scene file's resolution) keeps that default unless the user asked otherwise.
    bool given(const std::string& name) const;

private:
    struct Entry {
        std::string name, value_hint, help;
        bool takes_value;
        std::function<void(const std::string&)> set;  // throws InputError on a bad value
    };
    std::string program_, summary_;
    std::vector<Entry> entries_;
    std::vector<std::string> given_;
};

// The options every chapter program has.
struct CommonOptions {
    int width = 640;
    int height = 360;
    int spp = 1;
    int threads = 0;
    std::uint64_t seed = 1;
    std::string out;  // the figure's path; each program sets its default
    bool stats = false;
};

void add_common_options(CommandLine& cli, CommonOptions& options);

// The options of every program's --sweep: whether to run it, how many runs each measurement takes
// (the tables give their median, and a timed cell its spread), and where its CSV goes (the lesson
// tables go beside it, tables_beside in lesson_table.hpp).
struct SweepOptions {
    bool on = false;
    int repeat = 5;
    std::string csv;
};

// --sweep (with what it measures), --repeat and --csv; a program whose sweep times something else
// than one run per measurement, or writes more than one table, says so in its own help.
void add_sweep_options(CommandLine& cli, SweepOptions& sweep, const std::string& what,
                       const std::string& csv_help = "where --sweep writes its table",
                       const std::string& repeat_help = "runs per measurement; the tables give the median");

// A chapter program's command line: its name, what it shows (the first line of --help) and the
// common options, with its figure written to NAME.png unless --out says otherwise.
CommandLine program_command_line(const std::string& program, const std::string& summary, CommonOptions& common);

// Why 2^25 pixels (8192 x 4096): an image is 12 bytes a pixel of linear colour, and the noisy
// chapters keep a second one for the variance: 800 MB at this size, the most a render here should
// take of a student's machine. Larger is refused before the render (InputError naming the size).
constexpr long long max_image_pixels = 1LL << 25;
void check_image_size(int width, int height);

// The render the common options ask for (size, samples, threads, seed); checks the size.
RenderSettings render_settings(const CommonOptions& options);

// What every chapter program does without --sweep: renders its figure (timed), writes it to
// options.out, and prints the --stats lines when asked (print_stats, or the printer given).
// Returns the exit status: 0, or exit_kit_bug when a pixel came out NaN or infinite.
using StatsPrinter = std::function<void(std::ostream&, const Counts&, double)>;
// (For the kit's own tests: with the environment variable RT_POISON_PIXEL set, pixel (0, 0) is made
// NaN before the check, so a test can prove that every program returns this status.)
[[nodiscard]] int write_figure(const CommonOptions& options, const std::function<Image()>& render,
                               StatsPrinter print = print_stats);

// Runs a program's body, turning InputError into "program: message" on stderr and exit status 2.
int run_program(const std::string& program, const std::function<int()>& body);

}  // namespace rt
