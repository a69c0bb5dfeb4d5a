# The kit's dependencies, found wherever a platform's package manager puts them (apt, dnf, Homebrew,
# vcpkg, MSYS2): GLM and stb here, Catch2 in tests/. Never vendored. Each is looked for as its own
# CMake package (or pkg-config file) first, then by its headers on the usual paths and
# CMAKE_PREFIX_PATH; a cache variable names the folder where neither finds it.

# GLM: header-only. Its package (glmConfig.cmake) where one is installed, else glm/glm.hpp.
find_package(glm CONFIG QUIET)
if(NOT TARGET glm::glm)
  find_path(RT_GLM_INCLUDE_DIR glm/glm.hpp DOC "The folder holding glm/glm.hpp")
  if(NOT RT_GLM_INCLUDE_DIR)
    message(FATAL_ERROR "GLM not found: install it (libglm-dev, glm-devel, brew install glm, vcpkg install glm) "
      "or give -DRT_GLM_INCLUDE_DIR=/folder/holding/glm")
  endif()
  add_library(glm::glm INTERFACE IMPORTED)
  set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${RT_GLM_INCLUDE_DIR}")
endif()

# stb: header-only too, and packaged in two layouts: Debian and Fedora put the headers in
# include/stb/ with a pkg-config file (whose -I names that folder), vcpkg puts them flat in include/
# with none. The kit includes them flat (<stb_image.h>) from the folder that holds them, and compiles
# their implementation itself (rt_stb), so nothing links against a distribution's compiled stb.
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(RT_STB_PC QUIET stb)
endif()
find_path(RT_STB_INCLUDE_DIR stb_image.h HINTS ${RT_STB_PC_INCLUDE_DIRS} PATH_SUFFIXES stb
  DOC "The folder holding stb_image.h")
if(NOT RT_STB_INCLUDE_DIR)
  message(FATAL_ERROR "stb not found: install it (libstb-dev, stb-devel, vcpkg install stb, pacman -S "
    "mingw-w64-x86_64-stb) or give -DRT_STB_INCLUDE_DIR=/folder/holding/stb_image.h")
endif()
foreach(header stb_image_write.h stb_easy_font.h)
  if(NOT EXISTS "${RT_STB_INCLUDE_DIR}/${header}")
    message(FATAL_ERROR "${RT_STB_INCLUDE_DIR} holds stb_image.h but not ${header}: the kit needs both")
  endif()
endforeach()
if(RT_STB_PC_FOUND)
  message(STATUS "stb: ${RT_STB_INCLUDE_DIR} (pkg-config)")
else()
  message(STATUS "stb: ${RT_STB_INCLUDE_DIR} (its headers; no pkg-config file)")
endif()

# Floating-point std::from_chars: libstdc++ (GCC 11+) and MSVC have it, libc++ before LLVM 20 does
# not; the NFF reader then checks the same grammar itself (common/number.cpp).
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_FLAGS "${CMAKE_CXX_FLAGS}")
check_cxx_source_compiles([[
#include <charconv>
int main() { double v; const char t[] = "1.5"; return std::from_chars(t, t + 3, v).ec == std::errc() ? 0 : 1; }
]] RT_HAVE_FLOAT_FROM_CHARS)
unset(CMAKE_REQUIRED_FLAGS)

# Warnings: GCC's and clang's -Wall -Wextra, MSVC's /W4 (and UTF-8 sources, conforming mode).
if(MSVC)
  set(RT_WARNING_FLAGS /W4 /utf-8 /permissive-)
  # A stub's parameters are unused until the student writes the answer.
  set(RT_NO_UNUSED_PARAMETER_WARNING /wd4100)
else()
  set(RT_WARNING_FLAGS -Wall -Wextra)
  set(RT_NO_UNUSED_PARAMETER_WARNING -Wno-unused-parameter)
endif()

# The student's file (and a mutant of a solution) keeps its assertions in every build type: GLM
# asserts that a vector's index is below its length, so a loop that runs one component too far
# (a <= 3 over a vec3) stops its case with that message. A release build drops the assertion, and
# glm's vec3 answers v[3] with v.x: the loop quietly does x twice, often with the right answer.
# libstdc++'s _GLIBCXX_ASSERTIONS checks std::vector's and std::array's indices the same way (one
# past a table's last bucket reads whatever lies there); it changes no type's layout, and other
# standard libraries ignore it.
if(MSVC)
  set(RT_STUDENT_ASSERTIONS /UNDEBUG)
else()
  set(RT_STUDENT_ASSERTIONS -UNDEBUG -D_GLIBCXX_ASSERTIONS)
endif()

# Float formulas mean what they say: no multiply and add fused into one rounding where the compiler
# may choose to (GCC fuses across statements by default and clang within one, wherever the processor
# has FMA: ARM, Apple silicon, x86-64 built for a recent -march). The kit's exact answers rest on
# each product being rounded: chapter 10's four lanes answer as 02.5 does one triangle at a time,
# bit for bit, only if neither is fused differently from the other. MSVC 2022 fuses only when asked
# (/fp:contract); MSVC 2019 may under /arch:AVX2, which the kit never sets. clang-cl is clang.
# Measured: the kit built with -march=haswell and GCC's default (-ffp-contract=fast) answered 28 of 600
# rays of common/scenes/spheres.nff differently through the wide tree than brute force, and the
# solutions lost points in 10.6 and 10.A (the binary tree too); with it off, none.
if(MSVC AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(RT_FLOAT_FLAGS /fp:precise /clang:-ffp-contract=off)
elseif(MSVC)
  set(RT_FLOAT_FLAGS /fp:precise)
else()
  set(RT_FLOAT_FLAGS -ffp-contract=off)
endif()

# Threads: the kit's parallel loop is std::thread (common/parallel.hpp), OpenMP or not.
find_package(Threads REQUIRED)
