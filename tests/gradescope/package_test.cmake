# The Gradescope package, run as Gradescope would run it, in a throw-away copy of its layout:
# the package unpacked into autograder/source, a submission (chapter 01's solution, in a folder
# of its own as students upload them) in autograder/submission, then run_autograder, grading
# chapter 01 only. results.json must hold chapter 01's cases, at full points.
#   cmake -D SOURCE_DIR=<the kit> -D WORK=<a scratch folder> -P package_test.cmake
file(REMOVE_RECURSE "${WORK}/autograder")
execute_process(COMMAND "${CMAKE_COMMAND}" -D "SOURCE_DIR=${SOURCE_DIR}" -D "OUT=${WORK}"
  -P "${SOURCE_DIR}/tests/gradescope/package.cmake" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the package was not written")
endif()
set(root "${WORK}/autograder")
file(MAKE_DIRECTORY "${root}/source" "${root}/submission/my_work")
execute_process(COMMAND "${CMAKE_COMMAND}" -E tar xf "${WORK}/autograder.zip" WORKING_DIRECTORY "${root}/source")
foreach(file setup.sh run_autograder CMakeLists.txt tests/grade.cmake)
  if(NOT EXISTS "${root}/source/${file}")
    message(FATAL_ERROR "the package has no ${file} at its root")
  endif()
endforeach()
file(COPY "${SOURCE_DIR}/solutions/01_ray_casting.cpp" DESTINATION "${root}/submission/my_work")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "AUTOGRADER_ROOT=${root}" "RT_GRADE_CHAPTERS=01"
    bash "${root}/source/run_autograder"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT EXISTS "${root}/results/results.json")
  message(FATAL_ERROR "run_autograder failed (${rc}) or wrote no results:\n${out}")
endif()
file(READ "${root}/results/results.json" json)
string(REGEX MATCHALL "\"number\": \"01\\.[0-9A-Z]+\"" cases "${json}")
string(REGEX MATCHALL "\"max_score\": [0-9]+" maxima "${json}")
set(total 0)
foreach(m IN LISTS maxima)
  string(REGEX REPLACE "[^0-9]" "" points "${m}")
  math(EXPR total "${total} + ${points}")
endforeach()
list(LENGTH cases n)
if(n EQUAL 0 OR NOT json MATCHES "\"score\": ${total},")
  message(FATAL_ERROR "results.json should grade chapter 01's solution at its ${total} points over ${n} cases:\n${json}")
endif()
message(STATUS "the Gradescope package graded chapter 01's solution at ${total} points over ${n} cases")
