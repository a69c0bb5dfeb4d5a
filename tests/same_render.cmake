# Renders one scene twice, with two sets of options, and checks that the two pictures are the same
# byte for byte and that the two runs counted the same rays (every --stats line naming rays, hits
# or shadows): an accelerator must render brute force's image with brute force's rays.
#   cmake -D PROGRAM=... -D ARGS="a|b" -D FIRST="--accel|brute" -D SECOND="--accel|grid" -D OUT=prefix
#         [-D GENERATOR=nff_generate -D GENERATE="mountain|--depth|3"] -P same_render.cmake
# With GENERATOR, the scene is written first to OUT.nff and given as --scene. With EXPECT, the
# second run's --stats must match that regular expression too ("threads=2\n"). With SECOND_PROGRAM,
# the second run is that program's: two chapters' brute force must agree too.
string(REPLACE "|" ";" args "${ARGS}")
string(REPLACE "|" ";" first "${FIRST}")
string(REPLACE "|" ";" second "${SECOND}")
if(GENERATOR)
  string(REPLACE "|" ";" generate "${GENERATE}")
  execute_process(COMMAND "${GENERATOR}" ${generate} OUTPUT_FILE "${OUT}.nff" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${GENERATOR} ${generate}: exit status ${rc}")
  endif()
  list(APPEND args --scene "${OUT}.nff")
endif()
set(program_first "${PROGRAM}")
set(program_second "${PROGRAM}")
if(SECOND_PROGRAM)
  set(program_second "${SECOND_PROGRAM}")
endif()
foreach(run first second)
  execute_process(COMMAND "${program_${run}}" ${args} ${${run}} --stats --out "${OUT}-${run}.png"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${program_${run}} ${args} ${${run}}: exit status ${rc}\n${out}${err}")
  endif()
  string(REGEX MATCHALL "(rays(_primary|_shadow|_reflected|_refracted)?|eye_[a-z]+|[a-z]+_rays|shadow_blocked|secondary_hits)=[0-9]+\n" lines "${out}")
  set(counts_${run} "${lines}")
  set(output_${run} "${out}")
endforeach()
if(EXPECT AND NOT output_second MATCHES "${EXPECT}")
  message(FATAL_ERROR "${program_second} ${args} ${second}: its --stats do not match '${EXPECT}':\n${output_second}")
endif()
if(NOT counts_first STREQUAL counts_second)
  message(FATAL_ERROR "the two runs counted different rays:\n  ${program_first} ${FIRST}: ${counts_first}\n  "
    "${program_second} ${SECOND}: ${counts_second}")
endif()
if(counts_first STREQUAL "")
  message(FATAL_ERROR "no ray counts in the output of ${PROGRAM}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUT}-first.png" "${OUT}-second.png" RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "${OUT}-first.png (${FIRST}) and ${OUT}-second.png (${SECOND}) differ: the pictures must be "
    "the same byte for byte")
endif()
message(STATUS "same picture, same rays: ${counts_first}")
