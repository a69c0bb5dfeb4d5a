# The handout switches do what they say. HINT_TIERS=N keeps tiers 1 to N of every exercise's hints,
# counted for each N and for the default, which keeps all three (the walk-through included); 0
# leaves no hint. CONTRACTS=behaviour (the default) drops every
# `// DETAIL BEGIN` ... `// DETAIL END` block of steps from the contracts, markers and all; detailed
# keeps the steps and drops only the markers. No handout holds a solution or a mutant, and a
# handout configures. Malformed markers stop the handout rather than hand out the steps. No marker
# is left anywhere, dot-folders included. The handout's README and contract headers do not speak of
# solutions/. The first handouts carry GitHub Classroom's workflow and the stubs it restores (the
# handout's own exercises); the last, written with CLASSROOM=OFF, neither (the workflow's own test:
# classroom/workflow_test.cmake).
#   cmake -D KIT=<the kit> -D HINT=<the hint program> -D WORK=<a scratch folder> -P handout_test.cmake
cmake_minimum_required(VERSION 3.22)

# The contracts as each level should leave them, worked out here with one regular expression per
# level (tests/contract_detail.cmake walks the markers instead). A line of a block is any comment
# line but the END marker (strictly: one not starting `// DET`).
set(block_line "[ \t]*//(\n|[^ \n][^\n]*\n| \n| [^D\n][^\n]*\n| D\n| D[^E\n][^\n]*\n| DE\n| DE[^T\n][^\n]*\n)")
function(expected_contract text level out)
  # The handout has no solutions/: the header's sentence on where the reference answers are goes.
  string(REGEX REPLACE ";[ \n/]*the reference answers are in[ \n/]*solutions/[0-9a-z_]+\\.cpp\\." "." text "${text}")
  if(level STREQUAL "detailed")
    string(REGEX REPLACE "[ \t]*// DETAIL (BEGIN|END)[^\n]*\n" "" text "${text}")
  else()
    string(REGEX REPLACE "[ \t]*// DETAIL BEGIN[^\n]*\n(${block_line})*[ \t]*// DETAIL END[^\n]*\n" "" text "${text}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE kit_contracts RELATIVE "${KIT}" "${KIT}/chapters/*.hpp" "${KIT}/exercises/*.cpp")
set(marked_contracts "")
set(kit_blocks 0)
foreach(contract IN LISTS kit_contracts)
  file(READ "${KIT}/${contract}" text)
  string(REGEX MATCHALL "// DETAIL BEGIN" begins "${text}")
  list(LENGTH begins n)
  if(n GREATER 0)
    list(APPEND marked_contracts "${contract}")
    math(EXPR kit_blocks "${kit_blocks} + ${n}")
  endif()
endforeach()
if(kit_blocks EQUAL 0)
  message(FATAL_ERROR "no contract of ${KIT} has a `// DETAIL BEGIN` block: this test would prove nothing")
endif()

# Each setting: the hint tiers, and the contracts asked for (none: the default). The first is the
# default handout, which must keep all three tiers.
foreach(setting "default:" "3:" "2:" "1:" "0:detailed")
  string(REPLACE ":" ";" setting "${setting}")
  list(GET setting 0 tiers)
  list(GET setting 1 contracts)
  set(tiers_flag -D "HINT_TIERS=${tiers}")
  set(said "HINT_TIERS=${tiers}")
  set(out "${WORK}/tiers_${tiers}")
  if(tiers STREQUAL "default")
    set(tiers_flag "")
    set(said "HINT_TIERS unset (the default)")
    set(tiers 3)
    set(out "${WORK}/default")
  endif()
  set(contracts_flag "")
  set(level "behaviour")
  if(contracts)
    set(contracts_flag -D "CONTRACTS=${contracts}")
    set(level "${contracts}")
  endif()
  set(classroom ON)
  if(tiers EQUAL 0)
    set(classroom OFF)
  endif()
  execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${out}" ${tiers_flag} ${contracts_flag}
      -D "CLASSROOM=${classroom}" -P "${KIT}/tests/handout.cmake"
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "handout.cmake failed with ${said} ${contracts_flag}:\n${log}")
  endif()
  if(EXISTS "${out}/solutions" OR EXISTS "${out}/tests/mutants" OR EXISTS "${out}/tests/mutation" OR NOT EXISTS "${out}/exercises")
    message(FATAL_ERROR "the handout in ${out} should have exercises/ and neither solutions/ nor tests/mutants/ nor tests/mutation/")
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
    message(FATAL_ERROR "the handout with ${said} does not have ${tiers} tier(s) for every exercise:\n${log}")
  endif()
  message(STATUS "${said}: ${log}")

  # The contracts: no marker left anywhere in the handout, dot-folders included (Classroom's copy
  # of the stubs is in .github/): a contract's DETAIL markers, or a solution's cut markers, at the
  # start of a line, where the kit's contracts and solutions have them (the tools that read them
  # quote them mid-line). Each marked file exactly as its level says.
  file(GLOB_RECURSE handed_out LIST_DIRECTORIES false "${out}/*")
  set(dot_files 0)
  foreach(file IN LISTS handed_out)
    if(file MATCHES "/\\.")
      math(EXPR dot_files "${dot_files} + 1")
    endif()
    file(STRINGS "${file}" markers REGEX "^[ \t]*// (DETAIL (BEGIN|END)|SOLUTION (BEGIN|END)|STUB)")
    if(markers)
      message(FATAL_ERROR "CONTRACTS=${level}: ${file} still holds markers:\n${markers}")
    endif()
  endforeach()
  if(classroom AND dot_files EQUAL 0)
    message(FATAL_ERROR "the search for markers saw no file under a dot-folder of ${out}: it would miss .github/")
  endif()
  # The handout describes itself: its README never mentions solutions/ (nor keeps a kit-only
  # marker), and no contract header says where the reference answers are; each still says where the
  # student writes them.
  file(READ "${out}/README.md" readme)
  string(REGEX MATCH "[^\n]*(solutions/|kit only)[^\n]*" left "${readme}")
  if(left)
    message(FATAL_ERROR "the handout's README.md speaks of what the handout lacks:\n${left}")
  endif()
  file(GLOB headers "${out}/chapters/[0-9][0-9]_*/[0-9][0-9]_*.hpp")
  foreach(header IN LISTS headers)
    get_filename_component(name "${header}" NAME_WE)
    file(READ "${header}" text)
    string(REGEX REPLACE "\n// " " " text "${text}")
    if(text MATCHES "reference answers are in" OR NOT text MATCHES "You write them in exercises/${name}\\.cpp\\. Do not edit")
      string(SUBSTRING "${text}" 0 400 start)
      message(FATAL_ERROR "${header} should say the exercises are written in exercises/${name}.cpp and not where the reference answers are:\n${start}")
    endif()
  endforeach()

  # Classroom's stubs are the handout's own exercises, byte for byte.
  foreach(stub IN LISTS stubs)
    get_filename_component(name "${stub}" NAME)
    file(READ "${stub}" got)
    file(READ "${out}/exercises/${name}" want)
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "CONTRACTS=${level}: ${stub} is not the handout's exercises/${name}")
    endif()
  endforeach()
  foreach(contract IN LISTS marked_contracts)
    file(READ "${KIT}/${contract}" source)
    file(READ "${out}/${contract}" got)
    expected_contract("${source}" "${level}" want)
    if(NOT got STREQUAL want)
      message(FATAL_ERROR "CONTRACTS=${level}: ${out}/${contract} is not ${KIT}/${contract} with "
        "${level} contracts (${level} keeps the steps and drops the markers; behaviour drops both):\n${got}")
    endif()
    if(level STREQUAL "behaviour" AND got STREQUAL source)
      message(FATAL_ERROR "CONTRACTS=behaviour left ${contract} as it is")
    endif()
  endforeach()
  if(level STREQUAL "detailed")
    set(done "kept")
  else()
    set(done "dropped")
  endif()
  string(REPLACE ";" ", " files "${marked_contracts}")
  message(STATUS "CONTRACTS=${level}: no marker left; the ${kit_blocks} step block(s) ${done} (${files})")
endforeach()

# A setting that is neither level stops the handout.
execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${WORK}/bogus" -D CONTRACTS=steps -P "${KIT}/tests/handout.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "CONTRACTS is behaviour")
  message(FATAL_ERROR "handout.cmake accepted CONTRACTS=steps:\n${log}")
endif()

# Malformed markers stop the handout, the file untouched; a well-formed one is cut as it says.
set(good "// EXERCISE 99.1: what it returns.\n  // DETAIL BEGIN: how\n  // step 1, then step 2\n//\n  // DETAIL END\nvoid f() {}\n")
set(cases
  "good|${good}"
  "no_end|// EXERCISE 99.1: what.\n// DETAIL BEGIN\n// a step\nvoid f() {}\n"
  "no_begin|// EXERCISE 99.1: what.\n// a step\n// DETAIL END\nvoid f() {}\n"
  "code_inside|// EXERCISE 99.1: what.\n// DETAIL BEGIN\nvoid f() {}\n// DETAIL END\n"
  "nested|// DETAIL BEGIN\n// DETAIL BEGIN\n// DETAIL END\nvoid f() {}\n"
  "after_code|void f() {}  // DETAIL BEGIN\n// DETAIL END\n")
foreach(case IN LISTS cases)
  string(FIND "${case}" "|" bar)
  string(SUBSTRING "${case}" 0 ${bar} name)
  math(EXPR bar "${bar} + 1")
  string(SUBSTRING "${case}" ${bar} -1 text)
  set(file "${WORK}/markers/${name}.hpp")
  file(WRITE "${file}" "${text}")
  execute_process(COMMAND "${CMAKE_COMMAND}" -D "FILE=${file}" -P "${KIT}/tests/contract_detail.cmake"
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
  file(READ "${file}" after)
  if(name STREQUAL "good")
    if(NOT rc EQUAL 0 OR NOT after STREQUAL "// EXERCISE 99.1: what it returns.\nvoid f() {}\n")
      message(FATAL_ERROR "contract_detail.cmake cut a well-formed block wrongly (exit ${rc}):\n${after}\n${log}")
    endif()
  elseif(rc EQUAL 0 OR NOT after STREQUAL text)
    message(FATAL_ERROR "contract_detail.cmake accepted malformed markers (${name}), or changed the file:\n${text}\n${log}")
  endif()
endforeach()
file(WRITE "${WORK}/markers/good.hpp" "${good}")
execute_process(COMMAND "${CMAKE_COMMAND}" -D "FILE=${WORK}/markers/good.hpp" -D CONTRACTS=detailed -P "${KIT}/tests/contract_detail.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
file(READ "${WORK}/markers/good.hpp" after)
if(NOT rc EQUAL 0 OR NOT after STREQUAL "// EXERCISE 99.1: what it returns.\n  // step 1, then step 2\n//\nvoid f() {}\n")
  message(FATAL_ERROR "contract_detail.cmake with CONTRACTS=detailed should keep the steps and drop the markers (exit ${rc}):\n${after}\n${log}")
endif()

# A handout configures as it is (no target may need a solution or a mutant).
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${WORK}/tiers_0" -B "${WORK}/tiers_0/build"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the handout does not configure:\n${log}")
endif()

# SOLVED: chapters handed out solved. Each solved exercises/ file is its solution with the cutting
# marks taken out (no marker, no stub call, the solution's code whole), the Classroom stubs carry it,
# and neither Classroom nor the grade preset grades a solved chapter. A solved chapter also in
# CLASSROOM_CHAPTERS stops the handout. (Grading chapter 07 in such a handout, its earlier chapters
# solved: the stubs read as chapter 07's own, never as waiting on 02's; the solution scores full.)
set(out "${WORK}/solved")
execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${out}" -D "SOLVED=01;02;03;04;05;06" -P "${KIT}/tests/handout.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "handout.cmake with SOLVED=01;...;06 failed:\n${log}")
endif()
file(GLOB solved_files RELATIVE "${out}/exercises" "${out}/exercises/0[1-6]_*.cpp")
list(LENGTH solved_files n)
if(NOT n EQUAL 6)
  message(FATAL_ERROR "SOLVED=01;...;06: ${n} solved files in the handout's exercises/, not 6")
endif()
foreach(file IN LISTS solved_files)
  file(READ "${out}/exercises/${file}" given)
  file(READ "${out}/.github/classroom/stubs/${file}" classroom_copy)
  file(STRINGS "${KIT}/solutions/${file}" solution_lines REGEX "^[ \t]*return .*;$")
  list(GET solution_lines 0 first_return)
  if(given MATCHES "(^|\n)[ \t]*// (SOLUTION|STUB)" OR given MATCHES "stub\\(\"" OR NOT given MATCHES "given solved in this handout")
    message(FATAL_ERROR "SOLVED: exercises/${file} keeps a cutting mark or a stub call, or does not say it is given solved")
  endif()
  string(FIND "${given}" "${first_return}" at)
  if(at EQUAL -1 OR NOT classroom_copy STREQUAL given)
    message(FATAL_ERROR "SOLVED: exercises/${file} lacks the solution's code ('${first_return}'), or the Classroom stubs differ from it")
  endif()
endforeach()
# The lessons' "Before you start" lines keep only the unsolved chapters' exercises.
file(STRINGS "${out}/chapters/04_shadow_feelers/README.md" before_04 REGEX "Before you start")
file(STRINGS "${out}/chapters/08_mailboxing/README.md" before_08 REGEX "Before you start")
if(before_04 OR NOT before_08 MATCHES "run your 07\\.1, 07\\.2, 07\\.3, 07\\.4, 07\\.5 and 07\\.6\\. <!--")
  message(FATAL_ERROR "SOLVED=01;...;06: chapter 04's lesson should have no 'Before you start' line (all its earlier "
    "exercises are given) and chapter 08's should list 07.1-07.6 alone, not\n${before_04}\n${before_08}")
endif()
file(READ "${out}/CMakePresets.json" presets)
file(READ "${out}/.github/workflows/classroom.yml" workflow)
if(NOT presets MATCHES "\"RT_GRADE_CHAPTERS\": \"07;08;09;10\"" OR NOT workflow MATCHES "RT_GRADE_CHAPTERS: \"07;08;09;10\"")
  message(FATAL_ERROR "SOLVED=01;...;06: the grade preset and Classroom should grade 07;08;09;10 alone")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${WORK}/solved_and_graded" -D "SOLVED=01;02" -D "CLASSROOM_CHAPTERS=02;03"
    -P "${KIT}/tests/handout.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "chapter 02 is both SOLVED and in CLASSROOM_CHAPTERS")
  message(FATAL_ERROR "handout.cmake graded a solved chapter (SOLVED=01;02, CLASSROOM_CHAPTERS=02;03):\n${log}")
endif()
message(STATUS "SOLVED=01;...;06: six chapters given solved, graded 07-10 only")

# OPEN_EXERCISES: the open exercises assigned. The others stay in the handout, their lesson sections
# say they are not assigned, and the grade preset leaves their case files out of the graders (so
# Classroom, which grades through the preset, neither runs nor counts them). A name that is not one
# of the kit's open exercises stops the handout.
set(out "${WORK}/open_10_7")
execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${out}" -D "OPEN_EXERCISES=10.7" -D CLASSROOM=OFF -P "${KIT}/tests/handout.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "handout.cmake with OPEN_EXERCISES=10.7 failed:\n${log}")
endif()
file(READ "${out}/CMakePresets.json" presets)
file(READ "${out}/chapters/08_mailboxing/README.md" lesson_08)
file(READ "${out}/chapters/10_hierarchies/README.md" lesson_10)
if(NOT presets MATCHES "\"RT_OPEN_EXERCISES\": \"10.7\"")
  message(FATAL_ERROR "OPEN_EXERCISES=10.7: the grade preset should carry RT_OPEN_EXERCISES 10.7")
endif()
if(NOT lesson_08 MATCHES "\\(EXERCISE 08\\.4, open\\)\n\n> Not assigned in this course" OR lesson_10 MATCHES "Not assigned in this course")
  message(FATAL_ERROR "OPEN_EXERCISES=10.7: lesson 08's open section should say it is not assigned, lesson 10's not")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${out}" -B "${out}/build" -D RT_GRADE=ON -D RT_OPEN_EXERCISES=10.7
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the handout with OPEN_EXERCISES=10.7 does not configure to grade:\n${log}")
endif()
# The build files name each object they compile (build.ninja, or a Makefile's build.make), and a
# unity build's batches (RT_UNITY_TESTS) each file they include.
file(GLOB_RECURSE build_files "${out}/build/*.ninja" "${out}/build/*build.make" "${out}/build/*.vcxproj"
  "${out}/build/unity_*.cxx")
set(compiled "")
foreach(f IN LISTS build_files)
  file(STRINGS "${f}" lines REGEX "ch[0-9][0-9]/open_[a-z_]+\\.cpp")
  string(REGEX MATCHALL "ch[0-9][0-9]/open_[a-z_]+\\.cpp" found "${lines}")
  list(APPEND compiled ${found})
endforeach()
list(REMOVE_DUPLICATES compiled)
if(NOT compiled STREQUAL "ch10/open_build.cpp")
  message(FATAL_ERROR "OPEN_EXERCISES=10.7: the graders should compile ch10/open_build.cpp alone of the open cases, not '${compiled}'")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${WORK}/open_bogus" -D "OPEN_EXERCISES=10.8" -P "${KIT}/tests/handout.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "'10\\.8' is not one")
  message(FATAL_ERROR "handout.cmake took OPEN_EXERCISES=10.8, which is not an open exercise:\n${log}")
endif()
message(STATUS "OPEN_EXERCISES=10.7: 08.4 marked not assigned and left out of the graders")
