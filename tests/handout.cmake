# Writes the kit as handed out to students: without solutions/ and without the mutants (whose
# lines are the solutions'), with each chapter's hints cut to the tiers the course allows.
#
#   cmake -D OUT=<folder> [-D HINT_TIERS=3|2|1|0] [-D CLASSROOM_CHAPTERS="01;02"] [-D CLASSROOM=OFF]
#         -P tests/handout.cmake
#
# HINT_TIERS (default 3, all): the tiers of every chapters/NN_name/hints.md kept, 1 the idea, 2 the
# trap, 3 the walk-through; 0 leaves the hints out. The grader and the programs build the same.
# The handout is also a GitHub Classroom template: .github/workflows/classroom.yml grades every push
# (tests/classroom/classroom.yml) of the chapters in CLASSROOM_CHAPTERS (default: all), with a copy
# of the handed-out stubs in .github/classroom/stubs; CLASSROOM=OFF leaves both out.
get_filename_component(kit "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
if(NOT OUT)
  message(FATAL_ERROR "handout: say where to write it: -D OUT=<folder>")
endif()
if(NOT DEFINED HINT_TIERS)
  set(HINT_TIERS 3)
endif()
if(NOT HINT_TIERS MATCHES "^[0-3]$")
  message(FATAL_ERROR "handout: HINT_TIERS is 0, 1, 2 or 3 (the tiers kept), not '${HINT_TIERS}'")
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
foreach(entry CMakeLists.txt CMakePresets.json README.md .gitignore .ci .devcontainer chapters common exercises tests)
  if(EXISTS "${kit}/${entry}")
    file(COPY "${kit}/${entry}" DESTINATION "${OUT}")
  endif()
endforeach()
file(REMOVE_RECURSE "${OUT}/tests/mutants")
file(GLOB hint_files "${OUT}/chapters/*/hints.md")
foreach(hints IN LISTS hint_files)
  if(HINT_TIERS EQUAL 0)
    file(REMOVE "${hints}")
    continue()
  endif()
  file(READ "${hints}" text)
  # Each tier is one folded block; the ones above HINT_TIERS go.
  math(EXPR first_cut "${HINT_TIERS} + 1")
  foreach(tier RANGE ${first_cut} 3)
    string(REGEX REPLACE "<details><summary>[0-9][0-9]\\.[0-9A-Za-z]+, tier ${tier}:[^<]*</summary>[^<]*(<[^/][^<]*|</[^d][^<]*)*</details>\n*" "" text "${text}")
  endforeach()
  if(HINT_TIERS LESS 3)
    string(REGEX REPLACE "^(# [^\n]*\n)" "\\1\n(This handout keeps tiers 1 to ${HINT_TIERS} of each exercise's hints.)\n" text "${text}")
  endif()
  file(WRITE "${hints}" "${text}")
endforeach()
if(NOT DEFINED CLASSROOM OR CLASSROOM)
  if(NOT "${CLASSROOM_CHAPTERS}" MATCHES "^([0-9][0-9](;[0-9][0-9])*)?$")
    message(FATAL_ERROR "handout: CLASSROOM_CHAPTERS is a list of chapter numbers, \"01;02\", not '${CLASSROOM_CHAPTERS}'")
  endif()
  set(RT_GRADE_CHAPTERS "${CLASSROOM_CHAPTERS}")
  # The packages a student needs, from the one list (.ci/install-packages).
  file(READ "${kit}/.ci/install-packages" script)
  if(NOT script MATCHES "\npackages=\\(([^)]+)\\)")
    message(FATAL_ERROR "handout: .ci/install-packages has no line packages=(...)")
  endif()
  set(RT_PACKAGES "${CMAKE_MATCH_1}")
  configure_file("${kit}/tests/classroom/classroom.yml" "${OUT}/.github/workflows/classroom.yml" @ONLY)
  file(GLOB stubs "${kit}/exercises/[0-9][0-9]_*.cpp")
  file(COPY ${stubs} DESTINATION "${OUT}/.github/classroom/stubs")
  set(graded "every chapter")
  if(CLASSROOM_CHAPTERS)
    set(graded "chapters ${CLASSROOM_CHAPTERS}")
  endif()
  message(STATUS "GitHub Classroom's workflow, grading ${graded}: ${OUT}/.github/workflows/classroom.yml")
endif()
message(STATUS "the handout, with ${HINT_TIERS} tier(s) of hints: ${OUT}")
