#!/usr/bin/env bash
# CI job: README's long checks (`cmake --workflow --preset long`) in the test job's build, cut to fit
# CI's time: the Gradescope package and the batch of three (each its own build), the check that a
# stale lesson count is caught, and one chapter's lesson tables against its sweep, the chapter the
# mutation job takes today (ten days of runs cover all ten; RT_LESSON_CHAPTERS=07 or "all" chooses).
# Classroom's workflow runs in the clang-libcxx job, with the Catch2 v3 a Classroom runner has.
set -euo pipefail
cd "$(dirname "$0")/../.."
chapters=(01 02 03 04 05 06 07 08 09 10)
chosen=${RT_LESSON_CHAPTERS:-${chapters[$((10#$(date +%j) % 10))]}}
[ "$chosen" = all ] && chosen="[0-9][0-9]"
ctest --preset long -R "^(grader\.(gradescope_package|batch_class_of_three)|lessons\.(tables_${chosen}|check_catches_a_stale_count))$"
