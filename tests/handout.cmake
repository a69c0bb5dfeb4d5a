# Writes the kit as handed out to students: without solutions/ and without the mutants (whose
# lines are the solutions'), with each chapter's hints cut to the tiers the course allows and its
# contracts at the level the course chooses.
#
#   cmake -D OUT=<folder> [-D HINT_TIERS=3|2|1|0] [-D CONTRACTS=behaviour|detailed]
#         [-D CLASSROOM_CHAPTERS="01;02"] [-D CLASSROOM=OFF] -P tests/handout.cmake
#
# HINT_TIERS (default 3, all): the tiers of every chapters/NN_name/hints.md kept, 1 the idea, 2 the
# trap, 3 the walk-through; 0 leaves the hints out.
# CONTRACTS (default behaviour): each exercise's contract says what its function returns, and may
# carry a `// DETAIL BEGIN` ... `// DETAIL END` block of steps under it (tests/contract_detail.cmake).
# `behaviour` drops those blocks from every header and exercise; `detailed`, for an introductory
# course, keeps the steps and drops only the marker lines. The grader and the programs build the same.
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
if(NOT DEFINED CONTRACTS)
  set(CONTRACTS behaviour)
endif()
if(NOT CONTRACTS MATCHES "^(behaviour|detailed)$")
  message(FATAL_ERROR "handout: CONTRACTS is behaviour (what each function returns) or detailed (the steps too), not '${CONTRACTS}'")
endif()
include("${CMAKE_CURRENT_LIST_DIR}/contract_detail.cmake")
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
foreach(entry CMakeLists.txt CMakePresets.json README.md .gitignore .ci .devcontainer chapters common exercises tests)
  if(EXISTS "${kit}/${entry}")
    file(COPY "${kit}/${entry}" DESTINATION "${OUT}")
  endif()
endforeach()
file(REMOVE_RECURSE "${OUT}/tests/mutants")
# The machine-made mutants' list of equivalent ones quotes the solutions' lines too.
file(REMOVE_RECURSE "${OUT}/tests/mutation")
file(GLOB hint_files "${OUT}/chapters/*/hints.md")
foreach(hints IN LISTS hint_files)
  if(HINT_TIERS EQUAL 0)
    file(REMOVE "${hints}")
    continue()
  endif()
  file(READ "${hints}" text)
  # Each tier is one folded block; the ones above HINT_TIERS go. (None with 3: CMake's
  # foreach(RANGE 4 3) counts down, 4 then 3, and would drop the walk-throughs.)
  set(cut_tiers "")
  if(HINT_TIERS LESS 3)
    math(EXPR first_cut "${HINT_TIERS} + 1")
    foreach(tier RANGE ${first_cut} 3)
      list(APPEND cut_tiers ${tier})
    endforeach()
  endif()
  foreach(tier IN LISTS cut_tiers)
    string(REGEX REPLACE "<details><summary>[0-9][0-9]\\.[0-9A-Za-z]+, tier ${tier}:[^<]*</summary>[^<]*(<[^/][^<]*|</[^d][^<]*)*</details>\n*" "" text "${text}")
  endforeach()
  if(HINT_TIERS LESS 3)
    string(REGEX REPLACE "^(# [^\n]*\n)" "\\1\n(This handout keeps tiers 1 to ${HINT_TIERS} of each exercise's hints.)\n" text "${text}")
  endif()
  file(WRITE "${hints}" "${text}")
endforeach()
# The contracts at the chosen level: the headers of every chapter, and the exercises' comments.
file(GLOB_RECURSE contract_files "${OUT}/chapters/*.hpp" "${OUT}/exercises/*.cpp")
set(detail_blocks 0)
foreach(contract IN LISTS contract_files)
  file(READ "${contract}" text)
  string(FIND "${text}" "// DETAIL " marked)
  if(marked EQUAL -1)
    continue()
  endif()
  file(RELATIVE_PATH where "${OUT}" "${contract}")
  contract_detail("${text}" "${CONTRACTS}" "${where}" text blocks)
  file(WRITE "${contract}" "${text}")
  math(EXPR detail_blocks "${detail_blocks} + ${blocks}")
endforeach()
if(CONTRACTS STREQUAL "detailed")
  set(done "kept")
else()
  set(done "dropped")
endif()
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
  # The stubs as this handout has them (its contracts' level applied), not the kit's.
  file(GLOB stubs "${OUT}/exercises/[0-9][0-9]_*.cpp")
  file(COPY ${stubs} DESTINATION "${OUT}/.github/classroom/stubs")
  set(graded "every chapter")
  if(CLASSROOM_CHAPTERS)
    set(graded "chapters ${CLASSROOM_CHAPTERS}")
  endif()
  message(STATUS "GitHub Classroom's workflow, grading ${graded}: ${OUT}/.github/workflows/classroom.yml")
endif()
message(STATUS "the handout, with ${HINT_TIERS} tier(s) of hints and ${CONTRACTS} contracts (${detail_blocks} step blocks ${done}): ${OUT}")
