# Branch coverage of solutions/ under the graded cases alone, one chapter at a time (the coverage
# preset: `cmake --workflow --preset coverage`, which needs gcovr). Each chapter's grader of the
# solutions runs its graded and stability cases, and gcovr counts the branches of that chapter's
# solution file they reached (exception and unreachable branches left out). Writes
# BUILD_DIR/coverage.md and fails when a chapter is below GOAL percent.
#   cmake -D BUILD_DIR=... -D SOURCE_DIR=... -D CHAPTERS="01_ray_casting|..." -D GOAL=95 -P coverage.cmake
find_program(GCOVR gcovr)
if(NOT GCOVR)
  message(FATAL_ERROR "the coverage preset needs gcovr (apt-get install gcovr)")
endif()
string(REPLACE "|" ";" chapters "${CHAPTERS}")
set(table "| chapter | branches | reached | coverage | lines with a branch not reached |\n|---|---|---|---|---|\n")
set(below "")
foreach(chapter IN LISTS chapters)
  string(SUBSTRING "${chapter}" 0 2 nn)
  file(GLOB_RECURSE counts "${BUILD_DIR}/*.gcda")
  if(counts)
    file(REMOVE ${counts})
  endif()
  execute_process(COMMAND "${BUILD_DIR}/tests/grade_${nn}_solutions" --expect-score full
    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "chapter ${nn}: the solutions do not score full points under coverage (exit ${rc})")
  endif()
  execute_process(COMMAND "${GCOVR}" --root "${SOURCE_DIR}" --object-directory "${BUILD_DIR}"
      --filter "${SOURCE_DIR}/solutions/${chapter}\\.cpp" --exclude-throw-branches --exclude-unreachable-branches
      --branches
    OUTPUT_VARIABLE report RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT report MATCHES "solutions/${chapter}\\.cpp +([0-9]+) +([0-9]+) +([0-9]+)%([^\n]*)")
    message(FATAL_ERROR "chapter ${nn}: gcovr gave no branch count for solutions/${chapter}.cpp:\n${report}")
  endif()
  set(total ${CMAKE_MATCH_1})
  set(taken ${CMAKE_MATCH_2})
  set(percent ${CMAKE_MATCH_3})
  string(STRIP "${CMAKE_MATCH_4}" missing)
  if(missing STREQUAL "")
    set(missing "none")
  endif()
  string(APPEND table "| ${chapter} | ${total} | ${taken} | ${percent}% | ${missing} |\n")
  message(STATUS "${chapter}: ${taken} of ${total} branches (${percent}%)")
  if(percent LESS GOAL)
    list(APPEND below "${chapter} (${percent}%)")
  endif()
endforeach()
file(WRITE "${BUILD_DIR}/coverage.md" "${table}")
message("${table}")
message(STATUS "written ${BUILD_DIR}/coverage.md")
if(below)
  message(FATAL_ERROR "below the goal of ${GOAL}% branch coverage: ${below}")
endif()
