# The Gradescope package, run as Gradescope would run it, in a throw-away copy of its layout:
# the package, written for an assignment of chapter 01 alone (-D CHAPTERS=01, as a course with one
# assignment a chapter writes it), unpacked into autograder/source, setup.sh (which builds the kit
# once), a submission (chapter 01's solution, in a folder of its own as students upload them) in
# autograder/submission, then run_autograder, as Gradescope runs them: no setting of their own. The
# submission must compile only its own file, and results.json must hold chapter 01's cases alone,
# at full points. A package asked for a chapter the kit does not have is not written.
#   cmake -D KIT=<the kit> -D WORK=<a scratch folder> -P package_test.cmake
file(REMOVE_RECURSE "${WORK}/autograder")
foreach(bad "11" "1;2" "01,02")
  execute_process(COMMAND "${CMAKE_COMMAND}" -D "SOURCE_DIR=${KIT}" -D "OUT=${WORK}/bad" "-DCHAPTERS=${bad}"
    -P "${KIT}/tests/gradescope/package.cmake" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc EQUAL 0 OR NOT out MATCHES "gradescope package: CHAPTERS")
    message(FATAL_ERROR "a package for CHAPTERS=${bad} should not be written, and say why (${rc}):\n${out}")
  endif()
endforeach()
execute_process(COMMAND "${CMAKE_COMMAND}" -D "SOURCE_DIR=${KIT}" -D "OUT=${WORK}/bad" -D "OPEN_EXERCISES=10.8"
  -P "${KIT}/tests/gradescope/package.cmake" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0 OR NOT out MATCHES "gradescope package: OPEN_EXERCISES")
  message(FATAL_ERROR "a package for OPEN_EXERCISES=10.8 (no such open exercise) should not be written, and say why (${rc}):\n${out}")
endif()
# (OPEN_EXERCISES=10.7: the autograder's build leaves the other open exercises' cases out; checked
# below on its cache, since this assignment grades chapter 01 alone.)
execute_process(COMMAND "${CMAKE_COMMAND}" -D "SOURCE_DIR=${KIT}" -D "OUT=${WORK}" -D CHAPTERS=01 -D OPEN_EXERCISES=10.7
  -P "${KIT}/tests/gradescope/package.cmake" RESULT_VARIABLE rc)
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
# setup.sh, as Gradescope runs it when it builds the image (the packages are this machine's).
string(TIMESTAMP t0 "%s")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=RT_GRADE_CHAPTERS "AUTOGRADER_ROOT=${root}" RT_SKIP_PACKAGES=1
    bash "${root}/source/setup.sh"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(TIMESTAMP t1 "%s")
if(NOT rc EQUAL 0 OR NOT out MATCHES "the kit was built in")
  message(FATAL_ERROR "setup.sh failed (${rc}):\n${out}")
endif()
file(STRINGS "${root}/work/build/.ninja_log" built)
list(LENGTH built setup_log_lines)
file(STRINGS "${root}/work/build/CMakeCache.txt" open_setting REGEX "^RT_OPEN_EXERCISES:")
if(NOT open_setting MATCHES "=10\\.7$")
  message(FATAL_ERROR "the package was written with OPEN_EXERCISES=10.7; the autograder's build has '${open_setting}'")
endif()
file(COPY "${KIT}/solutions/01_ray_casting.cpp" DESTINATION "${root}/submission/my_work")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=RT_GRADE_CHAPTERS "AUTOGRADER_ROOT=${root}"
    bash "${root}/source/run_autograder"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
string(TIMESTAMP t2 "%s")
if(NOT rc EQUAL 0 OR NOT EXISTS "${root}/results/results.json")
  message(FATAL_ERROR "run_autograder failed (${rc}) or wrote no results:\n${out}")
endif()
# The submission compiled its own file and nothing else of the kit: the objects ninja built after
# setup.sh (its log gains a line per output built) are that file's alone.
file(STRINGS "${root}/work/build/.ninja_log" built)
list(LENGTH built n_built)
list(SUBLIST built ${setup_log_lines} -1 built_for_submission)
list(FILTER built_for_submission INCLUDE REGEX "\\.o(bj)?\t")
list(LENGTH built_for_submission n_compiled)
if(NOT n_compiled EQUAL 1 OR NOT built_for_submission MATCHES "01_ray_casting\\.cpp\\.o")
  message(FATAL_ERROR "a submission should compile only the student's file; it compiled ${n_compiled}:\n${built_for_submission}")
endif()
math(EXPR setup_s "${t1} - ${t0}")
math(EXPR grade_s "${t2} - ${t1}")
message(STATUS "setup.sh built the kit in ${setup_s} s; the submission was graded in ${grade_s} s")
file(READ "${root}/results/results.json" json)
string(REGEX MATCHALL "\"number\": \"01\\.[0-9A-Z]+\"" cases "${json}")
string(REGEX MATCHALL "\"max_score\": [0-9]+" maxima "${json}")
set(total 0)
foreach(m IN LISTS maxima)
  string(REGEX REPLACE "[^0-9]" "" points "${m}")
  math(EXPR total "${total} + ${points}")
endforeach()
list(LENGTH cases n)
string(REGEX MATCHALL "\"number\": \"(0[2-9]|10)[^\"]*\"" others "${json}")
if(others)
  message(FATAL_ERROR "the package was written for chapter 01 alone, yet results.json grades ${others}")
endif()
if(n EQUAL 0 OR NOT json MATCHES "\"score\": ${total},")
  message(FATAL_ERROR "results.json should grade chapter 01's solution at its ${total} points over ${n} cases:\n${json}")
endif()
message(STATUS "the Gradescope package graded chapter 01's solution at ${total} points over ${n} cases")
