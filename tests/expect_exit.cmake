# Runs a program and checks its exit status and what it printed.
#   cmake -D PROGRAM=... -D ARGS="a|b|c" -D STATUS=2 -D MATCH=regex -P expect_exit.cmake
#   -D NO_MATCH=regex fails when the output matches it.
#   -D POISON=1 sets RT_POISON_PIXEL, which makes write_figure poison one pixel (cli.hpp).
#   -D PROGRESS_SECONDS=S sets RT_PROGRESS_SECONDS, the period of progress lines in a log.
string(REPLACE "|" ";" args "${ARGS}")
if(POISON)
  set(ENV{RT_POISON_PIXEL} 1)
endif()
if(DEFINED PROGRESS_SECONDS)
  set(ENV{RT_PROGRESS_SECONDS} "${PROGRESS_SECONDS}")
endif()
execute_process(COMMAND "${PROGRAM}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT rc STREQUAL "${STATUS}")
  message(FATAL_ERROR "${PROGRAM} ${args}: exit status ${rc}, expected ${STATUS}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT "${out}${err}" MATCHES "${MATCH}")
  message(FATAL_ERROR "${PROGRAM} ${args}: printed\n${out}${err}\nwhich does not match '${MATCH}'")
endif()
if(DEFINED NO_MATCH AND "${out}${err}" MATCHES "${NO_MATCH}")
  message(FATAL_ERROR "${PROGRAM} ${args}: printed\n${out}${err}\nwhich should not match '${NO_MATCH}'")
endif()
