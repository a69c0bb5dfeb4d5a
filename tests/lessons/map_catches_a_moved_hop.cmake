# lessons.ray_trip_map_catches_a_moved_hop: the drawing's check fails when a hop of the list names
# another file than the drawing shows, and passes on the list as drawn.
#   cmake -D TOOL=trip_map -D KIT=<kit> -D WORK=dir -P map_catches_a_moved_hop.cmake
file(MAKE_DIRECTORY "${WORK}")
file(READ "${KIT}/chapters/programs/README.md" list)
file(WRITE "${WORK}/same.md" "${list}")
string(REGEX REPLACE "\n7\\. \\[`[^`]+`\\]" "\n7. [`common/image.hpp`]" moved "${list}")
if(moved STREQUAL list)
  message(FATAL_ERROR "the list has no hop 7 to move")
endif()
file(WRITE "${WORK}/moved.md" "${moved}")
foreach(case "same;0" "moved;1")
  list(GET case 0 name)
  list(GET case 1 expected)
  execute_process(COMMAND "${TOOL}" check "${WORK}/${name}.md" "${KIT}/chapters/programs/ray_trip.svg"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL expected)
    message(FATAL_ERROR "trip_map check on the ${name} list: expected exit ${expected}, got ${rc}:\n${out}")
  endif()
endforeach()
