# An open exercise's points and leaderboard entry, end to end: grades EXERCISE's cases with GRADER
# into RESULTS, checks that they sum to POINTS (a correct but costly build keeps its tier; a wrong
# one keeps nothing), then has REPORT (grade_report) write results.json as Gradescope reads it and
# the Classroom job summary, and checks the leaderboard: LEADERBOARD is the value it must hold, or
# "none" for a tree the gate failed (not ranked).
# cmake -D GRADER=... -D REPORT=... -D EXERCISE=10.7 -D POINTS=4 -D LEADERBOARD=1.742 -D RESULTS=...
#       -P open_tiers_test.cmake
execute_process(COMMAND "${GRADER}" "[${EXERCISE}]" --results "${RESULTS}" --case-timeout 20
  OUTPUT_VARIABLE out ERROR_VARIABLE out RESULT_VARIABLE ignored)
file(STRINGS "${RESULTS}" lines)
set(sum 0)
set(cases 0)
foreach(line IN LISTS lines)
  # A results line: number, max score, score, ... tab-separated (points.hpp).
  string(REGEX MATCH "^([^\t]*)\t[^\t]*\t([0-9]+)\t" fields "${line}")
  set(number "${CMAKE_MATCH_1}")
  set(score "${CMAKE_MATCH_2}")
  if(fields AND number STREQUAL EXERCISE)
    math(EXPR sum "${sum} + ${score}")
    math(EXPR cases "${cases} + 1")
  endif()
endforeach()
if(cases EQUAL 0)
  message(FATAL_ERROR "no case of ${EXERCISE} in ${RESULTS}:\n${out}")
endif()
if(NOT sum EQUAL POINTS)
  message(FATAL_ERROR "${EXERCISE} scored ${sum} points, expected ${POINTS}:\n${out}")
endif()

set(json "${RESULTS}.json")
set(summary "${RESULTS}.md")
file(REMOVE "${json}" "${summary}")
execute_process(COMMAND "${REPORT}" --json "${json}" --step-summary "${summary}" "${RESULTS}"
  OUTPUT_VARIABLE report_out ERROR_VARIABLE report_out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "grade_report failed (${rc}):\n${report_out}")
endif()
file(READ "${json}" results)
file(READ "${summary}" md)
if(LEADERBOARD STREQUAL "none")
  if(results MATCHES "leaderboard" OR md MATCHES "Your cost")
    message(FATAL_ERROR "a tree the gate failed is not ranked, yet results.json or the summary ranks it:\n${results}\n${md}")
  endif()
else()
  string(REPLACE "." "\\." value "${LEADERBOARD}")
  if(NOT results MATCHES "\"leaderboard\": \\[\n    {\"name\": \"${EXERCISE} cost\", \"value\": ${value}, \"order\": \"asc\"}\n  \\]")
    message(FATAL_ERROR "results.json should rank ${EXERCISE}'s cost ${LEADERBOARD}, lower first:\n${results}")
  endif()
  if(NOT md MATCHES "\\| ${EXERCISE} cost \\| ${value}[.0-9]* \\| 1\\.000 \\|")
    message(FATAL_ERROR "the Classroom summary should show ${EXERCISE}'s cost ${LEADERBOARD} against the reference's 1:\n${md}")
  endif()
endif()
message(STATUS "${EXERCISE}: ${sum} points, leaderboard ${LEADERBOARD}, as expected")
