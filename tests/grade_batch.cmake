# Batch grading: every submission folder under SUBMISSIONS (one per student, each holding that
# student's NN_name.cpp files) graded into one CSV gradebook.
#
#   cmake -D SUBMISSIONS=/path/to/class -P tests/grade_batch.cmake
#
# Optional: -D BUILD_DIR=... (default build/batch), -D GRADEBOOK=... (default BUILD_DIR/gradebook.csv),
# -D CHAPTERS="01;02" (default: every chapter), -D GENERATOR="Visual Studio 17 2022" (default: Ninja
# where it is installed, else CMake's default for the platform).
# One build folder serves every student: switching RT_EXERCISES_DIR rebuilds only the exercises.
# A student whose chapter is missing or does not compile scores 0 there, with every case of that
# chapter listed; the batch goes on, printing each student's total as it goes.
# Each student's results.json, junit.xml and report.html are kept under BUILD_DIR/students/NAME/,
# and BUILD_DIR/class.html links them all.
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
set(class_rows "${BUILD_DIR}/class-rows.html")
file(REMOVE "${GRADEBOOK}" "${class_rows}")
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
  # Every student's files compile afresh: a copied submission keeps its files' old times, older
  # than the objects a rerun of the batch left, and a build that trusts times would grade those.
  file(GLOB stale LIST_DIRECTORIES true "${BUILD_DIR}/CMakeFiles/ex_*.dir" "${BUILD_DIR}/ex_*.dir")
  if(stale)
    file(REMOVE_RECURSE ${stale})
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${source_dir}" -B "${BUILD_DIR}" ${generator}
      -D CMAKE_BUILD_TYPE=Release -D RT_GRADE=ON "-D RT_EXERCISES_DIR=${entry}" "-D RT_GRADE_CHAPTERS=${CHAPTERS}"
    RESULT_VARIABLE rc OUTPUT_QUIET)
  if(rc EQUAL 0)
    execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --config Release --target grade_report RESULT_VARIABLE rc)
  endif()
  if(NOT rc EQUAL 0)
    # Not this student's doing (their chapters build one by one when graded): say so, go on.
    message(WARNING "grade_batch: the kit did not build for ${student}; they are not graded")
    continue()
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
  file(MAKE_DIRECTORY "${BUILD_DIR}/students/${student}")
  file(COPY "${BUILD_DIR}/results.json" "${BUILD_DIR}/junit.xml" "${BUILD_DIR}/report.html"
    DESTINATION "${BUILD_DIR}/students/${student}")
endforeach()
# The class's page: every student's total, linking to their own report (images embedded in each),
# and each chapter's points, flagged where a file is missing, does not compile, is untouched, or
# had a case stopped (rows written by grade_report).
set(rows "")
if(EXISTS "${class_rows}")
  file(READ "${class_rows}" rows)
endif()
file(WRITE "${BUILD_DIR}/class.html" "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>The class</title>
<style>body{font-family:sans-serif;margin:2em}td,th{border:1px solid #ccc;padding:0.3em 0.6em}table{border-collapse:collapse}
td.ok{background:#dfd}td.part{background:#ffd}td.flag{background:#fdd}small{color:#733}</style>
</head><body><h1>The class</h1><p>Gradebook: gradebook.csv. A chapter's cell is flagged with what an instructor
should look at: no file, does not compile, untouched (still the handed-out stubs), an exercise still its
stub, a case stopped by its time limit or crashed.</p>
<table>\n${rows}</table></body></html>\n")
message(STATUS "class report: ${BUILD_DIR}/class.html")
message(STATUS "gradebook: ${GRADEBOOK}")
