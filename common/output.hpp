// Where a program's results go (a PNG, a CSV table): checked before the work that makes them, so
// that an hour's render is never lost to a folder that cannot be written.
#pragma once

#include <string>

namespace rt {

// Makes the folders `path` needs, and checks that the file can be written there without changing
// it if it exists: InputError "PATH: cannot write the WHAT file" otherwise (what: "PNG", "CSV").
void check_writable(const std::string& path, const std::string& what);

}  // namespace rt
