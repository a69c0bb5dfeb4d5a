#!/usr/bin/env bash
# CI job: one chapter's machine-made mutants a run (tests/mutation/README.md), graded in the test
# preset's build. The chapter rotates with the day of the year, so ten days of runs cover all ten;
# RT_MUTATION_CHAPTERS=07,08 (or all) chooses. A sample of RT_MUTATION_SAMPLE mutants (40; 0 for
# all), the same one every run, keeps the job to a minute or two on 2 cores. It prints the table and
# every survivor; a survivor does not fail the run (the table is the measure), a tool that breaks does.
set -euo pipefail
cd "$(dirname "$0")/../.."
chapters=(01 02 03 04 05 06 07 08 09 10)
chosen=${RT_MUTATION_CHAPTERS:-${chapters[$((10#$(date +%j) % 10))]}}
python3 tests/mutation/run.py --build build/test --chapters "$chosen" --sample "${RT_MUTATION_SAMPLE:-40}"
