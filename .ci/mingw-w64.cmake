# Cross-compiling the kit for Windows with Debian's mingw-w64 (g++-mingw-w64-x86-64-posix: the
# posix flavour, whose std::thread the kit's parallel loop needs). Used by .ci/jobs/windows.sh.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# One .exe with its C++ runtime inside, so it runs under wine (or on a Windows machine) as it is.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
