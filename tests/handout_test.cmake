# The handout switch does what it says: with HINT_TIERS=2 every exercise keeps tiers 1 and 2 and
# loses the walk-through; with 0 no hint is left; neither holds a solution or a mutant, and the
# handout configures.
#   cmake -D KIT=<the kit> -D HINT=<the hint program> -D WORK=<a scratch folder> -P handout_test.cmake
foreach(tiers 2 0)
  set(out "${WORK}/tiers_${tiers}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${out}" -D "HINT_TIERS=${tiers}" -P "${KIT}/tests/handout.cmake"
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "handout.cmake failed with HINT_TIERS=${tiers}:\n${log}")
  endif()
  if(EXISTS "${out}/solutions" OR EXISTS "${out}/tests/mutants" OR NOT EXISTS "${out}/exercises")
    message(FATAL_ERROR "the handout in ${out} should have exercises/ and neither solutions/ nor tests/mutants/")
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
