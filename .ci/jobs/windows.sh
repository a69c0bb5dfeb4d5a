#!/usr/bin/env bash
# CI job: the kit as Windows builds it, cross-compiled with Debian's mingw-w64: every program and
# grader, then chapter 01's program and graders run under wine, where wine starts (the graders'
# per-case processes are Windows processes there: CreateProcess, no fork).
#
# GLM, stb and Catch2 v2 are header-only: the build reads Debian's headers through a folder of
# links, so that nothing else of /usr/include (Linux's C library) reaches the Windows compiler.
# The test files compile one by one here (RT_UNITY_TESTS=OFF), not in batches as elsewhere: each
# graded file is checked to include what it uses.
set -euo pipefail
cd "$(dirname "$0")/../.."
kit=$(pwd)
work="$kit/build/ci-windows"
headers="$work/headers"
mkdir -p "$headers"
ln -sfn /usr/include/glm "$headers/glm"
ln -sfn /usr/include/catch2 "$headers/catch2"

cmake -S "$kit" -B "$work/build" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$kit/.ci/mingw-w64.cmake" -DCMAKE_BUILD_TYPE=Release \
  -DRT_GLM_INCLUDE_DIR="$headers" -DRT_STB_INCLUDE_DIR=/usr/include/stb -DRT_CATCH2_INCLUDE_DIR="$headers" \
  -DRT_CATCH2_MAJOR=2 -DRT_UNITY_TESTS=OFF >/dev/null
cmake --build "$work/build" --target programs_and_graders

wine=""
for w in wine64 /usr/lib/wine/wine64 wine; do
  if command -v "$w" >/dev/null 2>&1; then wine=$w; break; fi
done
if [ -z "$wine" ]; then
  echo "windows: built; wine is not installed, so nothing was run"
  exit 0
fi
export WINEDEBUG=-all WINEPREFIX="$work/wineprefix"
# The prefix made and settled before the first program: wine makes it on first use and goes on
# updating it in the background, and a grader's per-case process started meanwhile once failed to
# start ("could not start a process", one case of 50).
"$wine" wineboot --init >/dev/null 2>&1 || true
for server in wineserver /usr/lib/wine/wineserver64 /usr/lib/wine/wineserver; do
  if command -v "$server" >/dev/null 2>&1; then "$server" --wait || true; break; fi
done
# Relative paths: the Windows build's command line reads a leading '/' as an option's.
cd "$work"
run() { echo "+ wine $*"; "$wine" "$@"; }
run build/01_ray_casting.exe --width 64 --height 36 --threads 2 --stats --out 01.png
[ -s 01.png ] || { echo "windows: 01_ray_casting.exe wrote no picture" >&2; exit 1; }
rm -rf grade
run build/tests/grade_01_solutions.exe --expect-score full --case-timeout 60 --results grade/solutions.results \
  --artifacts grade/pictures
run build/tests/grade_01.exe --expect-score zero --case-timeout 60 --results grade/stubs.results --artifacts grade/pictures
