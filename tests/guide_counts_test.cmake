# The instructors' guide says how many points and graded cases the kit holds ("807 points in 365
# graded cases"): those two numbers must be what the graders hold now. Each chapter's grader lists
# its cases with their points (--list-cases, running none); their count and sum are compared with
# the guide's sentence, which must appear exactly once.
#   cmake -D "GRADERS=<grade_01_solutions>|...|<grade_10_solutions>" -D GUIDE=<tests/README.md>
#         -D WORK=<a scratch folder> -P guide_counts_test.cmake
string(REPLACE "|" ";" graders "${GRADERS}")
file(MAKE_DIRECTORY "${WORK}")
set(points 0)
set(cases 0)
foreach(grader IN LISTS graders)
  get_filename_component(name "${grader}" NAME_WE)
  set(list "${WORK}/${name}.cases")
  file(REMOVE "${list}")
  execute_process(COMMAND "${grader}" --list-cases "${list}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0 OR NOT EXISTS "${list}")
    message(FATAL_ERROR "${grader} --list-cases failed (${rc}):\n${out}")
  endif()
  # One case a line: number, maximum points, score, name, ... (points.hpp's results format). Read
  # whole, not as a CMake list: a case's name may hold a bracket or a semicolon, which would join
  # or split the list's items.
  file(READ "${list}" text)
  string(REGEX MATCHALL "(^|\n)[0-9][0-9]\\.[0-9A-Za-z]+\t[0-9]+\t" heads "${text}")
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH heads n)
  list(LENGTH newlines lines)
  if(NOT n EQUAL lines)
    message(FATAL_ERROR "${list}: ${lines} lines, of which ${n} begin as a case does (number, points)")
  endif()
  foreach(head IN LISTS heads)
    string(REGEX MATCH "\t([0-9]+)\t" points_field "${head}")
    math(EXPR points "${points} + ${CMAKE_MATCH_1}")
  endforeach()
  math(EXPR cases "${cases} + ${n}")
endforeach()
file(READ "${GUIDE}" guide)
string(REGEX MATCHALL "[0-9]+ points in [0-9]+ graded cases" said "${guide}")
list(LENGTH said n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "${GUIDE}: the sentence \"N points in M graded cases\" should appear once, not ${n} times")
endif()
if(NOT said STREQUAL "${points} points in ${cases} graded cases")
  message(FATAL_ERROR "${GUIDE} says \"${said}\"; the graders hold ${points} points in ${cases} graded cases: write that")
endif()
message(STATUS "${GUIDE}: ${said}, as the graders hold")
