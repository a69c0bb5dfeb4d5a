# An open exercise's points, exactly: grades EXERCISE's cases with GRADER into RESULTS and checks
# that they sum to POINTS (a correct but costly build keeps its tier; a wrong one keeps nothing).
# cmake -D GRADER=... -D EXERCISE=10.7 -D POINTS=4 -D RESULTS=... -P open_tiers_test.cmake
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
message(STATUS "${EXERCISE}: ${sum} points, as expected")
