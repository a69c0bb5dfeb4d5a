# Writes Gradescope's autograder package: OUT/autograder.zip, the kit (solutions too, when it has
# them, so a chapter is graded with the solutions of the chapters before it) with setup.sh and
# run_autograder at the zip's root, as Gradescope wants them; it unpacks the zip into
# /autograder/source.
#   cmake -D SOURCE_DIR=<the kit> -D OUT=<folder> [-D CHAPTERS="07;08"] [-D OPEN_EXERCISES="10.7"] -P package.cmake
# CHAPTERS: the chapters this assignment grades (a course with one assignment a chapter writes one
# package each); none: all ten. Written to graded_chapters.txt, which run_autograder reads.
# OPEN_EXERCISES: the open exercises assigned (all, the default, none, or a list;
# tests/open_exercises.cmake). Written to open_exercises.txt, which run_autograder reads.
if(NOT "${CHAPTERS}" MATCHES "^([0-9][0-9](;[0-9][0-9])*)?$")
  message(FATAL_ERROR "gradescope package: CHAPTERS is a list of chapter numbers, \"07;08\", not '${CHAPTERS}'")
endif()
foreach(nn IN LISTS CHAPTERS)
  file(GLOB chapter "${SOURCE_DIR}/exercises/${nn}_*.cpp")
  if(NOT chapter)
    message(FATAL_ERROR "gradescope package: CHAPTERS names chapter ${nn}, which the kit does not have (exercises/${nn}_*.cpp)")
  endif()
endforeach()
include("${SOURCE_DIR}/tests/open_exercises.cmake")
rt_open_assigned(assigned_open "${OPEN_EXERCISES}" "${SOURCE_DIR}/tests" "gradescope package: OPEN_EXERCISES")
set(stage "${OUT}/package")
file(REMOVE_RECURSE "${stage}")
file(MAKE_DIRECTORY "${stage}")
if(CHAPTERS)
  file(WRITE "${stage}/graded_chapters.txt" "${CHAPTERS}")
endif()
if(OPEN_EXERCISES)
  file(WRITE "${stage}/open_exercises.txt" "${OPEN_EXERCISES}")
endif()
# (Not CMakePresets.json: the autograder calls CMake itself, and the presets need CMake 3.25.)
foreach(entry CMakeLists.txt README.md chapters common exercises solutions tests)
  if(EXISTS "${SOURCE_DIR}/${entry}")
    file(COPY "${SOURCE_DIR}/${entry}" DESTINATION "${stage}")
  endif()
endforeach()
file(COPY "${SOURCE_DIR}/tests/gradescope/setup.sh" "${SOURCE_DIR}/tests/gradescope/run_autograder"
  DESTINATION "${stage}")
file(GLOB entries RELATIVE "${stage}" "${stage}/*")
file(REMOVE "${OUT}/autograder.zip")
execute_process(COMMAND "${CMAKE_COMMAND}" -E tar cf "${OUT}/autograder.zip" --format=zip ${entries}
  WORKING_DIRECTORY "${stage}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not write ${OUT}/autograder.zip")
endif()
set(graded "every chapter")
if(CHAPTERS)
  set(graded "chapters ${CHAPTERS}")
endif()
string(JOIN ", " open_words ${assigned_open})
if(NOT assigned_open)
  set(open_words "none")
endif()
string(APPEND graded " (open exercises: ${open_words})")
message(STATUS "wrote ${OUT}/autograder.zip, grading ${graded}: upload it as the assignment's autograder (Ubuntu image)")
