#!/usr/bin/env bash
# CI job: every libFuzzer target (tests/fuzz/README.md) builds with clang, and each runs briefly over
# its corpus (RT_FUZZ_SECONDS each, 12 by default): a finding fails the job and leaves its input
# under build/ci-fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")/../.."
work=build/ci-fuzz
seconds=${RT_FUZZ_SECONDS:-12}
cmake -S . -B "$work/build" -G Ninja -DRT_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release >/dev/null
# Every target tests/fuzz/CMakeLists.txt adds, by name.
targets=$(sed -n 's/^ *rt_add_\(solutions_\)\{0,1\}fuzz_target(\([a-z_][a-z_]*\).*/\2/p' tests/fuzz/CMakeLists.txt | sort -u)
cmake --build "$work/build" --target $targets
mkdir -p "$work/artifacts"
for target in $targets; do
  corpus=()
  # The NFF readers start from the kit's corpus of scene files; the others from nothing.
  case "$target" in nff_fuzz | scene_render_fuzz) corpus=(tests/fuzz/corpus -dict=tests/fuzz/nff.dict) ;; esac
  rm -rf "$work/$target-work"
  mkdir -p "$work/$target-work"
  echo "+ $target for $seconds s"
  "$work/build/tests/fuzz/$target" "$work/$target-work" "${corpus[@]}" -max_len=4096 -max_total_time="$seconds" \
    -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/artifacts/$target-" 2>&1 |
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|==.*ERROR|SUMMARY|.*contract broken)" || true
  if ls "$work/artifacts/$target-"* >/dev/null 2>&1; then
    echo "fuzz: $target found an input that breaks its contract: $(ls "$work/artifacts/$target-"*)" >&2
    exit 1
  fi
done
