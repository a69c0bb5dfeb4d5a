# Batch grading: every submission folder under SUBMISSIONS (one per student, each holding that
# student's NN_name.cpp files, or a clone of their repository, whose files are under exercises/)
# graded into one CSV gradebook.
#
#   cmake -D SUBMISSIONS=/path/to/class -P tests/grade_batch.cmake
#
# Optional: -D BUILD_DIR=... (default build/batch), -D GRADEBOOK=... (default BUILD_DIR/gradebook.csv),
# -D EXERCISES=... (default exercises.csv beside the gradebook), -D CHAPTERS="01;02" (default: every
# chapter), -D OPEN_EXERCISES="10.7" (the open exercises assigned: all, the default, none, or a list;
# tests/open_exercises.cmake), -D GENERATOR="Visual Studio 17 2022" (default: Ninja where it is installed, else CMake's
# default for the platform).
# One build folder serves every student: switching RT_EXERCISES_DIR rebuilds only the exercises.
# A student whose chapter is missing or does not compile scores 0 there, with every case of that
# chapter listed; the batch goes on, printing each student's total as it goes.
# Each student's results.json, junit.xml, report.html and chapters' results files (NN.results) are
# kept under BUILD_DIR/students/NAME/, and BUILD_DIR/class.html links them all; below the students,
# it gives each exercise's share at full marks, mean points and most failed cases (grade_report
# --class-page computes them from the results files), also written to EXERCISES as CSV.
# The open exercises' leaderboards (07.7's, 08.4's, 09.6's and 10.7's costs, lower first; only correct answers ranked) close the
# class page, and BUILD_DIR/leaderboard.html holds them alone, to share with the class: -D
# LEADERBOARD=pseudonyms shows each student there by a pseudonym (the class page lists each beside
# the name), from -D PSEUDONYM_KEY=any text you keep to yourself (the same key, the same pseudonyms
# at every regrade; without one, anyone with the class list could work them out). Default: names.
get_filename_component(source_dir "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
if(NOT SUBMISSIONS OR NOT IS_DIRECTORY "${SUBMISSIONS}")
  message(FATAL_ERROR "grade_batch: SUBMISSIONS=${SUBMISSIONS} is not a folder (-D SUBMISSIONS=/path/to/class)")
endif()
if(NOT BUILD_DIR)
  set(BUILD_DIR "${source_dir}/build/batch")
endif()
if(NOT GRADEBOOK)
  set(GRADEBOOK "${BUILD_DIR}/gradebook.csv")
endif()
if(NOT LEADERBOARD)
  set(LEADERBOARD names)
endif()
include("${source_dir}/tests/open_exercises.cmake")
rt_open_assigned(assigned_open "${OPEN_EXERCISES}" "${source_dir}/tests" "grade_batch: OPEN_EXERCISES")
if(NOT LEADERBOARD MATCHES "^(names|pseudonyms)$")
  message(FATAL_ERROR "grade_batch: LEADERBOARD takes names or pseudonyms, got '${LEADERBOARD}'")
endif()
if(NOT EXERCISES)
  get_filename_component(book_dir "${GRADEBOOK}" DIRECTORY)
  set(EXERCISES "${book_dir}/exercises.csv")
endif()
set(class_rows "${BUILD_DIR}/class-rows.html")
file(REMOVE "${GRADEBOOK}" "${EXERCISES}" "${class_rows}")
set(graded "")
# Any generator serves: Ninja where there is one, else the platform's (make, or Visual Studio, which
# builds several configurations: hence --config and -C below).
set(generator "")
if(GENERATOR)
  set(generator -G "${GENERATOR}")
elseif(NOT EXISTS "${BUILD_DIR}/CMakeCache.txt")
  find_program(ninja NAMES ninja ninja-build)
  if(ninja)
    set(generator -G Ninja)
  endif()
endif()
file(GLOB entries LIST_DIRECTORIES true "${SUBMISSIONS}/*")
list(SORT entries)
foreach(entry IN LISTS entries)
  if(NOT IS_DIRECTORY "${entry}")
    continue()
  endif()
  get_filename_component(student "${entry}" NAME)
  message(STATUS "==== ${student}")
  # A clone of a student's repository (GitHub Classroom's "Download repositories") keeps the files
  # where the handout put them, under exercises/; a folder of files holds them at its top.
  set(files "${entry}")
  file(GLOB top "${entry}/[0-9][0-9]_*.cpp")
  file(GLOB cloned "${entry}/exercises/[0-9][0-9]_*.cpp")
  if(NOT top AND cloned)
    set(files "${entry}/exercises")
    message(STATUS "${student}: a clone, graded from its exercises/")
  endif()
  # Every student's files compile afresh: a copied submission keeps its files' old times, older
  # than the objects a rerun of the batch left, and a build that trusts times would grade those.
  file(GLOB stale LIST_DIRECTORIES true "${BUILD_DIR}/CMakeFiles/ex_*.dir" "${BUILD_DIR}/ex_*.dir")
  if(stale)
    file(REMOVE_RECURSE ${stale})
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${source_dir}" -B "${BUILD_DIR}" ${generator}
      -D CMAKE_BUILD_TYPE=Release -D RT_GRADE=ON "-D RT_EXERCISES_DIR=${files}" "-D RT_GRADE_CHAPTERS=${CHAPTERS}"
      "-D RT_OPEN_EXERCISES=${OPEN_EXERCISES}"
    RESULT_VARIABLE rc OUTPUT_QUIET)
  if(rc EQUAL 0)
    execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --config Release --target grade_report RESULT_VARIABLE rc)
  endif()
  if(NOT rc EQUAL 0)
    # Not this student's doing (their chapters build one by one when graded): say so, go on.
    message(WARNING "grade_batch: the kit did not build for ${student}; they are not graded")
    continue()
  endif()
  # Only this student's chapters' results (an earlier batch may have graded other chapters).
  file(GLOB stale "${BUILD_DIR}/grade-results/*.results")
  if(stale)
    file(REMOVE ${stale})
  endif()
  set(ENV{RT_GRADEBOOK} "${GRADEBOOK}")
  set(ENV{RT_STUDENT} "${student}")
  set(ENV{RT_CLASS_ROWS} "${class_rows}")
  # Shown as it goes (the first student's chapters build the kit, minutes on a busy machine) and
  # kept, for the total.
  execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" --test-dir "${BUILD_DIR}" -C Release -R "^grade$" --output-on-failure -V
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log ECHO_OUTPUT_VARIABLE ECHO_ERROR_VARIABLE)
  string(REGEX MATCH "total +[0-9]+ / [0-9]+" total "${log}")
  if(NOT rc EQUAL 0 OR NOT total)
    message(WARNING "grade_batch: grading ${student} did not finish:\n${log}")
    continue()
  endif()
  string(REGEX REPLACE "total +" "" total "${total}")
  message(STATUS "${student}: ${total}")
  file(REMOVE_RECURSE "${BUILD_DIR}/students/${student}")
  file(MAKE_DIRECTORY "${BUILD_DIR}/students/${student}")
  file(GLOB chapter_results "${BUILD_DIR}/grade-results/*.results")
  file(COPY "${BUILD_DIR}/results.json" "${BUILD_DIR}/junit.xml" "${BUILD_DIR}/report.html" ${chapter_results}
    DESTINATION "${BUILD_DIR}/students/${student}")
  list(APPEND graded "${BUILD_DIR}/students/${student}")
endforeach()
# The class's page: every student's total, linking to their own report (images embedded in each),
# and each chapter's points, flagged where a file is missing, does not compile, is untouched, or
# had a case stopped (rows written by grade_report); then each exercise's statistics over the
# students graded in this batch, from their results files.
file(GLOB report LIST_DIRECTORIES false "${BUILD_DIR}/tests/grade_report" "${BUILD_DIR}/tests/grade_report.exe"
  "${BUILD_DIR}/tests/*/grade_report.exe")
if(NOT report)
  message(WARNING "grade_batch: the kit never built (no grade_report under ${BUILD_DIR}/tests): no class page")
  return()
endif()
list(GET report 0 report)
execute_process(COMMAND "${report}" --class-page "${BUILD_DIR}/class.html" --class-rows "${class_rows}"
    --link-gradebook "${GRADEBOOK}" --exercises-csv "${EXERCISES}" --leaderboard ${LEADERBOARD}
    --pseudonym-key "${PSEUDONYM_KEY}" --leaderboard-page "${BUILD_DIR}/leaderboard.html" ${graded}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "grade_batch: the class page could not be written (${rc})")
endif()
message(STATUS "class report: ${BUILD_DIR}/class.html")
message(STATUS "gradebook: ${GRADEBOOK}")
message(STATUS "per exercise: ${EXERCISES}")
