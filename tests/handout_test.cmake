# The handout switch does what it says: with HINT_TIERS=2 every exercise keeps tiers 1 and 2 and
# loses the walk-through; with 0 no hint is left; neither holds a solution or a mutant, and the
# handout configures. The first carries GitHub Classroom's workflow and the stubs it restores; the
# second, written with CLASSROOM=OFF, neither (the workflow's own test: classroom/workflow_test.cmake).
#   cmake -D KIT=<the kit> -D HINT=<the hint program> -D WORK=<a scratch folder> -P handout_test.cmake
foreach(tiers 2 0)
  set(out "${WORK}/tiers_${tiers}")
  set(classroom ON)
  if(tiers EQUAL 0)
    set(classroom OFF)
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${out}" -D "HINT_TIERS=${tiers}" -D "CLASSROOM=${classroom}"
      -P "${KIT}/tests/handout.cmake"
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "handout.cmake failed with HINT_TIERS=${tiers}:\n${log}")
  endif()
  if(EXISTS "${out}/solutions" OR EXISTS "${out}/tests/mutants" OR NOT EXISTS "${out}/exercises")
    message(FATAL_ERROR "the handout in ${out} should have exercises/ and neither solutions/ nor tests/mutants/")
  endif()
  file(GLOB stubs "${out}/.github/classroom/stubs/*.cpp")
  file(GLOB exercises "${out}/exercises/*.cpp")
  list(LENGTH stubs n_stubs)
  list(LENGTH exercises n_exercises)
  if(classroom AND (NOT EXISTS "${out}/.github/workflows/classroom.yml" OR NOT n_stubs EQUAL n_exercises))
    message(FATAL_ERROR "the handout in ${out} should carry .github/workflows/classroom.yml and a stub for each of its ${n_exercises} exercises")
  elseif(NOT classroom AND EXISTS "${out}/.github")
    message(FATAL_ERROR "the handout in ${out} was written with CLASSROOM=OFF, yet has .github/")
  endif()
  execute_process(COMMAND "${HINT}" --check ${tiers} --kit "${out}" RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the handout with HINT_TIERS=${tiers} does not have ${tiers} tier(s) for every exercise:\n${log}")
  endif()
  message(STATUS "HINT_TIERS=${tiers}: ${log}")
endforeach()
# A handout configures as it is (no target may need a solution or a mutant).
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${WORK}/tiers_0" -B "${WORK}/tiers_0/build"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the handout does not configure:\n${log}")
endif()
