#include "common/cli.hpp"

#include "common/output.hpp"
#include "common/png.hpp"
#include "common/stats.hpp"
#include "common/stub.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <limits>
#include <new>
#include <sstream>
#include <vector>

namespace rt {

CommandLine::CommandLine(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary))
{
}

void CommandLine::flag(const std::string& name, bool& target, const std::string& help)
{
    entries_.push_back({name, "", help, false, [&target](const std::string&) { target = true; }});
}

template <class Int>
static Int parse_whole(const std::string& name, const std::string& text)
{
    Int value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec == std::errc::result_out_of_range)
        throw InputError(name + " is out of range: '" + text + "'");
    if (ec != std::errc() || ptr != end)
        throw InputError(name + " takes a whole number, got '" + text + "'");
    return value;
}

void CommandLine::option(const std::string& name, int& target, const std::string& help, int min, int max)
{
    entries_.push_back({name, "N", help, true, [&target, name, min, max](const std::string& text) {
                            const int value = parse_whole<int>(name, text);
                            if (value < min || value > max)
                                throw InputError(name + " must be between " + std::to_string(min) + " and " +
                                                 std::to_string(max) + ", got " + text);
                            target = value;
                        }});
}

void CommandLine::option(const std::string& name, std::uint64_t& target, const std::string& help)
{
    entries_.push_back({name, "N", help, true, [&target, name](const std::string& text) {
                            target = parse_whole<std::uint64_t>(name, text);
                        }});
}

void CommandLine::option(const std::string& name, float& target, const std::string& help, float above, float below)
{
    entries_.push_back({name, "X", help, true, [&target, name, above, below](const std::string& text) {
                            char* end = nullptr;
                            const float value = std::strtof(text.c_str(), &end);
                            if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
                                throw InputError(name + " takes a finite number, got '" + text + "'");
                            if (!(value > above && value < below)) {
                                std::ostringstream message;
                                message << name << " must lie strictly between " << above << " and " << below
                                        << ", got " << text;
                                throw InputError(message.str());
                            }
                            target = value;
                        }});
}

void CommandLine::option(const std::string& name, std::string& target, const std::string& help)
{
    entries_.push_back({name, "TEXT", help, true, [&target, name](const std::string& text) {
                            if (text.empty())
                                throw InputError(name + " takes a non-empty value");
                            target = text;
                        }});
}

bool CommandLine::parse(int argc, const char* const* argv, std::ostream& out)
{
    given_.clear();
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        if (arg == "--help" || arg == "-h") {
            print_usage(out);
            return false;
        }
        const Entry* found = nullptr;
        for (const Entry& e : entries_)
            if (e.name == arg)
                found = &e;
        if (!found)
            throw InputError("unknown option '" + arg + "' (try --help)");
        given_.push_back(arg);
        if (!found->takes_value) {
            found->set("");
            continue;
        }
        if (k + 1 >= argc)
            throw InputError(arg + " needs a value");
        found->set(argv[++k]);
    }
    return true;
}

bool CommandLine::given(const std::string& name) const
{
    return std::find(given_.begin(), given_.end(), name) != given_.end();
}

void CommandLine::print_usage(std::ostream& out) const
{
    out << "usage: " << program_ << " [options]\n" << summary_ << "\n\noptions:\n";
    for (const Entry& e : entries_) {
        const std::string left = e.name + (e.takes_value ? " " + e.value_hint : "");
        out << "  " << std::left << std::setw(22) << left << e.help << '\n';
    }
    out << "  " << std::left << std::setw(22) << "--help" << "print this and exit\n";
}

void add_common_options(CommandLine& cli, CommonOptions& o)
{
    cli.option("--width", o.width, "image width in pixels", 1, 16384);
    cli.option("--height", o.height, "image height in pixels", 1, 16384);
    cli.option("--spp", o.spp, "samples per pixel (1 samples the pixel centre)", 1, 65536);
    cli.option("--threads", o.threads, "render threads (0: all cores); the image does not change", 0, 1024);
    cli.option("--seed", o.seed, "seed of the per-pixel random streams");
    cli.option("--out", o.out, "where to write the PNG");
    cli.flag("--stats", o.stats, "print what the render did, one key=value per line");
}

CommandLine program_command_line(const std::string& program, const std::string& summary, CommonOptions& common)
{
    common.out = program + ".png";
    CommandLine cli(program, summary);
    add_common_options(cli, common);
    return cli;
}

void add_sweep_options(CommandLine& cli, SweepOptions& sweep, const std::string& what, const std::string& csv_help,
                       const std::string& repeat_help)
{
    cli.flag("--sweep", sweep.on, what);
    cli.option("--repeat", sweep.repeat, repeat_help, 1, 100);
    cli.option("--csv", sweep.csv, csv_help);
}

void check_image_size(int width, int height)
{
    const long long pixels = static_cast<long long>(width) * height;
    if (pixels > max_image_pixels)
        throw InputError("an image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels needs about " +
                         std::to_string(pixels * 12 / 1000000) + " MB of colour; the limit is " +
                         std::to_string(max_image_pixels) + " pixels (8192 x 4096): choose a smaller --width or --height");
}

RenderSettings render_settings(const CommonOptions& o)
{
    check_image_size(o.width, o.height);
    RenderSettings s;
    s.width = o.width;
    s.height = o.height;
    s.spp = o.spp;
    s.threads = o.threads;
    s.seed = o.seed;
    return s;
}

namespace {

// A picture drawn by unfinished exercises is a handout's first picture, not a bug: say so, so a
// flat or empty figure is not mistaken for the chapter's answer.
void say_which_stubs_ran(const std::string& out)
{
    const std::vector<std::string> stubs = stubs_that_ran();
    if (stubs.empty())
        return;
    std::cerr << out << " was drawn with " << stubs.size() << (stubs.size() == 1 ? " exercise still a stub:" : " exercises still stubs:");
    for (const std::string& s : stubs)
        std::cerr << ' ' << s;
    std::cerr << " (grep -n \"EXERCISE " << stubs.front() << "\" exercises/*.cpp to start)\n";
}

}  // namespace

int write_figure(const CommonOptions& options, const std::function<Image()>& render, StatsPrinter print)
{
    check_writable(options.out, "PNG");
    const Timer timer;
    Image image = render();
    const double seconds = timer.seconds();
    if (std::getenv("RT_POISON_PIXEL") && !image.pixels.empty())
        image.pixels[0].r = std::numeric_limits<float>::quiet_NaN();
    write_png(options.out, image);
    if (options.stats)
        print(std::cout, total_counts(), seconds);
    say_which_stubs_ran(options.out);
    // A NaN or an infinity is the kit's own bug, never the input's: the PNG shows such pixels in
    // magenta (to_srgb8), and the exit status says so, so no test passes over one.
    if (const int bad = count_non_finite(image); bad > 0) {
        std::cerr << "a NaN or infinite radiance reached " << bad << " pixels of " << options.out
                  << " (shown magenta): a bug of the kit\n";
        return exit_kit_bug;
    }
    return 0;
}

int run_program(const std::string& program, const std::function<int()>& body)
{
    try {
        return body();
    } catch (const InputError& e) {
        std::cerr << program << ": " << e.what() << '\n';
        return exit_bad_input;
    } catch (const std::bad_alloc&) {
        // Every structure counts its size before it allocates and keeps within its budget, so this
        // is a machine with less memory than the scene and image need, not a crash to report.
        std::cerr << program << ": out of memory: the scene, the image or the acceleration structure needs more "
                     "memory than this machine has free\n";
        return exit_bad_input;
    } catch (const std::exception& e) {
        // Anything else is the kit's own failure (a structure that disagrees with brute force, say):
        // one line and its exit status, never an abort.
        std::cerr << program << ": " << e.what() << " (a bug of the kit)\n";
        return exit_kit_bug;
    }
}

}  // namespace rt
