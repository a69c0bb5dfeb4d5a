#include "common/output.hpp"

#include "common/error.hpp"

#include <filesystem>
#include <fstream>

namespace rt {

void check_writable(const std::string& path, const std::string& what)
{
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty())
        fs::create_directories(parent, ec);
    const bool existed = fs::exists(path, ec);
    // Opened for appending, an existing file keeps its contents; a new one is removed again.
    const bool writable = static_cast<bool>(std::ofstream(path, std::ios::app | std::ios::binary));
    if (writable && !existed)
        fs::remove(path, ec);
    if (!writable || fs::is_directory(path, ec))
        throw InputError(path + ": cannot write the " + what + " file");
}

}  // namespace rt
