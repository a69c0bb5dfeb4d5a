# Runs every chapter's grader on the student's code, whatever each one scores, then merges their
# results into a points table, results.json (Gradescope) and junit.xml in OUT_DIR.
# Called by the `grade` test of the grade preset with GRADERS (|-separated paths), REPORT, OUT_DIR.
string(REPLACE "|" ";" graders "${GRADERS}")
set(results "")
foreach(grader IN LISTS graders)
  get_filename_component(name "${grader}" NAME_WE)
  set(result "${OUT_DIR}/grade-results/${name}.results")
  file(MAKE_DIRECTORY "${OUT_DIR}/grade-results")
  message(STATUS "---- ${name}")
  # A student's endless loop must not hang the grading: two minutes a chapter at most.
  execute_process(COMMAND "${grader}" --results "${result}" --artifacts "${OUT_DIR}/grade-results/pictures"
    TIMEOUT 120 RESULT_VARIABLE rc)
  if(NOT rc MATCHES "^[0-9]+$")
    message(STATUS "${name} did not finish (${rc}): the cases after the last one reported score 0")
  endif()
  list(APPEND results "${result}")
endforeach()
execute_process(COMMAND "${REPORT}" --json "${OUT_DIR}/results.json" --junit "${OUT_DIR}/junit.xml" ${results}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the grade report could not be written in full (${rc})")
endif()
