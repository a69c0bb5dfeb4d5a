#include "tests/grader/child_process.hpp"

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iterator>
#include <thread>

#ifdef _WIN32
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
#else
#include <csignal>
#include <spawn.h>
#include <sys/wait.h>
extern char** environ;
#endif

namespace rt::grader {

const char* null_device()
{
#ifdef _WIN32
    return "NUL";
#else
    return "/dev/null";
#endif
}

void limit_cpu_time(double cpu_seconds, int code, std::function<void()> last_words)
{
    std::thread([cpu_seconds, code, last_words] {
        while (process_cpu_seconds() < cpu_seconds)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (last_words)
            last_words();
        std::_Exit(code);
    }).detach();
}

#ifdef _WIN32

namespace {

std::wstring widen(const std::string& s)
{
    if (s.empty())
        return {};
    const int n = MultiByteToWideChar(CP_UTF8, 0, s.data(), static_cast<int>(s.size()), nullptr, 0);
    std::wstring w(static_cast<size_t>(n), L'\0');
    MultiByteToWideChar(CP_UTF8, 0, s.data(), static_cast<int>(s.size()), w.data(), n);
    return w;
}

// One argument quoted as the C runtime splits a command line: backslashes are literal except
// before a quote, where they are doubled, and the quote escaped.
void append_quoted(std::wstring& line, const std::wstring& arg)
{
    if (!line.empty())
        line += L' ';
    if (!arg.empty() && arg.find_first_of(L" \t\n\v\"") == std::wstring::npos) {
        line += arg;
        return;
    }
    line += L'"';
    for (size_t k = 0;; ++k) {
        size_t backslashes = 0;
        while (k < arg.size() && arg[k] == L'\\') {
            ++k;
            ++backslashes;
        }
        if (k == arg.size()) {
            line.append(backslashes * 2, L'\\');
            break;
        }
        if (arg[k] == L'"')
            line.append(backslashes * 2 + 1, L'\\');
        else
            line.append(backslashes, L'\\');
        line += arg[k];
    }
    line += L'"';
}

double seconds_of(const FILETIME& t)
{
    ULARGE_INTEGER u;
    u.LowPart = t.dwLowDateTime;
    u.HighPart = t.dwHighDateTime;
    return static_cast<double>(u.QuadPart) * 1e-7;  // in units of 100 ns
}

}  // namespace

std::string this_program(const char* argv0)
{
    wchar_t path[32768];
    const DWORD n = GetModuleFileNameW(nullptr, path, static_cast<DWORD>(std::size(path)));
    if (n == 0 || n >= std::size(path))
        return argv0;
    return std::filesystem::path(std::wstring(path, n)).u8string();
}

double process_cpu_seconds()
{
    FILETIME created, exited, kernel, user;
    if (!GetProcessTimes(GetCurrentProcess(), &created, &exited, &kernel, &user))
        return 0.0;
    return seconds_of(kernel) + seconds_of(user);
}

ChildStatus run_child(const std::string& program, const std::vector<std::string>& args, double wall_seconds)
{
    std::wstring line;
    append_quoted(line, widen(program));
    for (const std::string& a : args)
        append_quoted(line, widen(a));
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    PROCESS_INFORMATION process{};
    ChildStatus status;
    if (!CreateProcessW(widen(program).c_str(), line.data(), nullptr, nullptr, TRUE, 0, nullptr, nullptr, &startup,
                        &process))
        return status;
    CloseHandle(process.hThread);
    if (WaitForSingleObject(process.hProcess, static_cast<DWORD>(wall_seconds * 1000.0)) == WAIT_TIMEOUT) {
        TerminateProcess(process.hProcess, 1);
        WaitForSingleObject(process.hProcess, INFINITE);
        status.end = ChildStatus::End::stopped;
    } else {
        DWORD code = 0;
        GetExitCodeProcess(process.hProcess, &code);
        // An unhandled exception (an access violation, 0xC0000005) ends a process with its code.
        status.end = code >= 0xC0000000u ? ChildStatus::End::crashed : ChildStatus::End::exited;
        status.code = static_cast<int>(code);
    }
    CloseHandle(process.hProcess);
    return status;
}

#else

std::string this_program(const char* argv0)
{
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);  // Linux
    return error ? std::string(argv0) : self.string();
}

double process_cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

ChildStatus run_child(const std::string& program, const std::vector<std::string>& args, double wall_seconds)
{
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(program.c_str()));
    for (const std::string& a : args)
        argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ChildStatus status;
    pid_t pid = 0;
    // posix_spawnp finds a bare program name on PATH, as the shell that started this one did.
    if (posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
        return status;
    int wstatus = 0;
    bool finished = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wall_seconds);
    while (!(finished = waitpid(pid, &wstatus, WNOHANG) == pid) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!finished) {
        kill(pid, SIGKILL);
        waitpid(pid, &wstatus, 0);
        status.end = ChildStatus::End::stopped;
    } else if (WIFSIGNALED(wstatus)) {
        status.end = ChildStatus::End::crashed;
        status.code = WTERMSIG(wstatus);
    } else {
        status.end = ChildStatus::End::exited;
        status.code = WEXITSTATUS(wstatus);
    }
    return status;
}

#endif

}  // namespace rt::grader
