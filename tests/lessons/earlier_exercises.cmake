# A lesson's "Before you start" line names every exercise of an earlier chapter that the chapter's
# graded cases run, so a student writes them all before the first grade, not one run at a time.
# The list comes from the solutions traced (kit_tool trace): each exercise notes that it ran, and
# the grader's results list them per case.
#   cmake -D NN=07 -D LESSON=<chapters/07_uniform_grid/README.md> -D GRADER=<grade_07_traced>
#         -D RESULTS=<file> -P earlier_exercises.cmake
include("${CMAKE_CURRENT_LIST_DIR}/earlier_line.cmake")
file(REMOVE "${RESULTS}")
execute_process(COMMAND "${GRADER}" --results "${RESULTS}" OUTPUT_QUIET ERROR_QUIET)
# The results: a line a case, its fields split by tabs; the sixth lists the exercises that ran.
file(STRINGS "${RESULTS}" lines)
if(NOT lines)
  message(FATAL_ERROR "grade_${NN}_traced graded no case (${RESULTS}): this check would prove nothing")
endif()
list(LENGTH lines cases)
set(earlier "")
foreach(line IN LISTS lines)
  # A regex, not a list: a description may hold brackets or semicolons, which split a list wrongly.
  if(NOT line MATCHES "^([^\t]*)\t([^\t]*)\t([^\t]*)\t([^\t]*)\t([^\t]*)\t([^\t]*)")
    continue()
  endif()
  string(REPLACE " " ";" ran "${CMAKE_MATCH_6}")
  foreach(exercise IN LISTS ran)
    string(SUBSTRING "${exercise}" 0 2 chapter)
    if(chapter LESS NN)
      list(APPEND earlier "${exercise}")
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES earlier)
list(SORT earlier COMPARE NATURAL)
list(LENGTH earlier count)
rt_earlier_line(expected ${earlier})
file(STRINGS "${LESSON}" marked REGEX "<!-- earlier exercises -->")
if(count EQUAL 0)
  if(marked)
    message(FATAL_ERROR "${LESSON}: its cases run no earlier exercise, so its line '${marked}' should go")
  endif()
  message(STATUS "chapter ${NN}: its ${cases} cases run no earlier exercise")
  return()
endif()
if(NOT marked STREQUAL expected)
  message(FATAL_ERROR "${LESSON}: its cases run ${earlier} of the earlier chapters; the line under its title should read\n"
    "${expected}\nnot\n${marked}")
endif()
message(STATUS "chapter ${NN}: its ${cases} cases run ${earlier}, as its lesson says")
