# Grades a student's exercises: builds and runs every chapter's grader in turn, whatever each one
# scores, then merges their results into a points table, results.json (Gradescope) and junit.xml.
#
# Called by the `grade` test of the grade preset, and by grade_batch.cmake once per submission:
#   cmake -D BUILD_DIR=... -D CHAPTERS="01|02" -D REPORT=.../grade_report -D SOURCE_DIR=<the kit>
#         -D EXERCISES_DIR=<the submission> -D GRADERS_DIR=<where grade_NN is built> [-D CONFIG=Release]
#         -P grade.cmake
# (CONFIG: the configuration to build with a multi-configuration generator, as Visual Studio's.)
# with the environment variables RT_GRADEBOOK=file.csv and RT_STUDENT=name set, it also appends
# the student's row to that gradebook (and with RT_CLASS_ROWS=file, to the class page's table).
# A chapter that does not compile scores 0 and shows the compiler's first lines; a case that loops
# forever or crashes loses its own points only.
string(REPLACE "|" ";" chapters "${CHAPTERS}")
set(config "")
if(CONFIG)
  set(config --config "${CONFIG}")
endif()
message(STATUS "==== grading the exercises in ${EXERCISES_DIR}")
set(out "${BUILD_DIR}/grade-results")
file(MAKE_DIRECTORY "${out}")
set(results "")
foreach(nn IN LISTS chapters)
  set(result "${out}/${nn}.results")
  file(REMOVE "${result}")
  message(STATUS "---- chapter ${nn}: building")
  execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" ${config} --target grade_${nn}
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    # Keep the compiler's errors, one line each, for the student's report. CMake's lists are
    # strings split at semicolons, and the commonest error is "expected ';' before ...": each
    # semicolon is kept apart as a placeholder while the lines pass through the list commands.
    string(REPLACE ";" "<rt-semicolon>" log_lines "${log}")
    string(REGEX MATCHALL "[^\n]*error[^\n]*" errors "${log_lines}")
    list(SUBLIST errors 0 12 errors)
    string(JOIN "\\n" errors ${errors})
    string(REPLACE "<rt-semicolon>" ";" errors "${errors}")
    string(REPLACE "\t" " " errors "${errors}")
    # Paths as the student knows them: their own file by name, the kit's relative to it.
    string(REPLACE "${EXERCISES_DIR}/" "" errors "${errors}")
    string(REPLACE "${SOURCE_DIR}/" "" errors "${errors}")
    # Every case of the chapter at 0, listed by a grader linked with the kit's own stubs, so the
    # maximum stays whole; then the line that says why, which the report shows in their place.
    execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" ${config} --target cases_${nn} OUTPUT_QUIET ERROR_QUIET)
    execute_process(COMMAND "${GRADERS_DIR}/cases_${nn}" --list-cases "${result}" OUTPUT_QUIET ERROR_QUIET)
    # One line for the chapter (grade_report counts it as all of the chapter's cases): a missing
    # file says so, a file that does not compile gives the compiler's first errors. The fields are
    # points.hpp's: number, max, score, name, output, stubs (none), status.
    if(errors MATCHES "the submission has no ([^ \"]+\\.cpp)")
      set(why "the submission has no ${CMAKE_MATCH_1}")
      set(errors "")
      set(status no_file)
    else()
      set(why "chapter ${nn} does not compile, so none of its cases ran. The compiler's first errors:")
      set(status does_not_compile)
    endif()
    file(APPEND "${result}" "${nn}.build\t0\t0\t${why}\t${errors}\t\t${status}\n")
    message(STATUS "chapter ${nn} does not compile:\n${log}")
  else()
    message(STATUS "---- chapter ${nn}: grading")
    # Each case in its own process, ten seconds at most: the solutions need well under one.
    execute_process(COMMAND "${GRADERS_DIR}/grade_${nn}" --results "${result}" --artifacts "${out}/pictures"
      --case-timeout 10)
  endif()
  list(APPEND results "${result}")
endforeach()
set(book "")
if(DEFINED ENV{RT_GRADEBOOK})
  set(book --gradebook "$ENV{RT_GRADEBOOK}" --student "$ENV{RT_STUDENT}")
endif()
if(DEFINED ENV{RT_CLASS_ROWS})
  list(APPEND book --class-row "$ENV{RT_CLASS_ROWS}" --student "$ENV{RT_STUDENT}")
endif()
execute_process(COMMAND "${REPORT}" --json "${BUILD_DIR}/results.json" --junit "${BUILD_DIR}/junit.xml"
    --html "${BUILD_DIR}/report.html" --title "the exercises in ${EXERCISES_DIR}"
    ${book} ${results}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grade report could not be written in full (${rc})")
endif()
