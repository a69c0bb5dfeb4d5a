#include "tests/grader/freshness.hpp"

#include "tests/grader/child_process.hpp"

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace rt::grader {

namespace {

std::vector<std::string>& exercise_sources()
{
    static std::vector<std::string> sources;
    return sources;
}

std::vector<std::string>& rebuild_command()
{
    static std::vector<std::string> command;
    return command;
}

std::string command_line(const std::vector<std::string>& words)
{
    std::string line;
    for (const std::string& w : words)
        line += (line.empty() ? "" : " ") + (w.find(' ') == std::string::npos ? w : '"' + w + '"');
    return line;
}

}  // namespace

bool register_exercise_sources(std::vector<std::string> sources, std::vector<std::string> command)
{
    exercise_sources() = std::move(sources);
    rebuild_command() = std::move(command);
    return true;
}

std::optional<int> regrade_if_stale(const std::string& program, int argc, char** argv)
{
    namespace fs = std::filesystem;
    // The rebuilt grader, started from here, does not look again: one rebuild, whatever the clocks say.
    if (exercise_sources().empty() || std::getenv("RT_GRADER_REBUILT"))
        return std::nullopt;
    std::error_code error;
    const auto built = fs::last_write_time(program, error);
    if (error)
        return std::nullopt;
    // Every file newer than the program, by name: an earlier chapter's exercise counts as much as
    // this chapter's (chapter 02's picture draws with 01.1).
    std::string changed;
    for (const std::string& source : exercise_sources()) {
        const auto edited = fs::last_write_time(source, error);
        if (!error && edited > built)
            changed += (changed.empty() ? "" : ", ") + fs::path(source).filename().string();
    }
    if (changed.empty())
        return std::nullopt;
    const std::string rebuild = command_line(rebuild_command());
    std::cout << changed << " changed after this grader was built: rebuilding it first\n  "
              << rebuild << '\n';
    std::cout.flush();
#ifdef _WIN32
    // Windows cannot replace a program while it runs.
    std::cout << "Windows cannot rebuild a program while it runs: run that command, then this one again.\n";
    return 2;
#else
    const std::vector<std::string> args(rebuild_command().begin() + 1, rebuild_command().end());
    const ChildStatus built_now = run_child(rebuild_command().front(), args, 3600.0);
    if (built_now.end != ChildStatus::End::exited || built_now.code != 0) {
        std::cout << "the rebuild failed (the compiler's messages are above): nothing was graded\n";
        return 2;
    }
    // A file that changed without changing the program (a contract's comment) leaves the build
    // nothing to do and the program as old as it was: dated now, it is not rebuilt at every run.
    if (fs::last_write_time(program, error) <= built && !error)
        fs::last_write_time(program, fs::file_time_type::clock::now(), error);
    const std::vector<std::string> same(argv + 1, argv + argc);
    setenv("RT_GRADER_REBUILT", "1", 1);
    const ChildStatus graded = run_child(program, same, 24 * 3600.0);
    return graded.end == ChildStatus::End::exited ? graded.code : 1;
#endif
}

}  // namespace rt::grader
