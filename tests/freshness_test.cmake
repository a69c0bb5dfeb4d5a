# A filtered grade grades the code as it is now, whichever file the grader links was edited: in a
# handout (no solutions/, so chapter 02's grader links the student's chapter 01 as well as 02), the
# student writes chapter 01's exercises after building grade_02. `grade_02 "[02.P]"` must say that
# 01_ray_casting.cpp changed, rebuild, and draw its picture with the new 01.1: no stub of chapter 01
# named any more. Run again, it grades at once (nothing changed). Its own build of chapters 01-02.
#   cmake -D KIT=<the kit> -D WORK=<a scratch folder> -P freshness_test.cmake
cmake_minimum_required(VERSION 3.22)
set(handout "${WORK}/handout")
set(build "${WORK}/build")
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND "${CMAKE_COMMAND}" -D "OUT=${handout}" -D CLASSROOM=OFF -P "${KIT}/tests/handout.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the handout could not be written:\n${log}")
endif()
set(generator "")
find_program(NINJA NAMES ninja ninja-build)
if(NINJA)
  set(generator -G Ninja)
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${handout}" -B "${build}" ${generator} -D CMAKE_BUILD_TYPE=Release
    -D RT_GRADE=ON "-D RT_GRADE_CHAPTERS=01;02"
  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(rc EQUAL 0)
  execute_process(COMMAND "${CMAKE_COMMAND}" --build "${build}" --config Release --target grade_02
    RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE log)
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the handout's grade_02 did not build:\n${log}")
endif()
file(GLOB grader LIST_DIRECTORIES false "${build}/tests/grade_02" "${build}/tests/grade_02.exe" "${build}/tests/*/grade_02.exe")

function(grade label)
  execute_process(COMMAND ${grader} "[02.P]" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message(STATUS "${label}: grade_02 \"[02.P]\" exited with ${rc}:\n${out}")
  set(rc ${rc} PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
endfunction()

# The stubs everywhere: the picture names chapter 01's stubs it drew with.
grade(stubs)
if(NOT out MATCHES "01\\.1")
  message(FATAL_ERROR "with chapter 01 untouched, grade_02 \"[02.P]\" should name 01.1 among the stubs that drew it")
endif()

# Chapter 01 written (the reference answers, as a student who finished it), grade_02 not rebuilt.
file(READ "${KIT}/solutions/01_ray_casting.cpp" solution)
file(WRITE "${handout}/exercises/01_ray_casting.cpp" "${solution}")
grade(edited)
if(WIN32)
  if(NOT rc EQUAL 2 OR NOT out MATCHES "01_ray_casting\\.cpp changed after this grader was built")
    message(FATAL_ERROR "after an edit of chapter 01, grade_02 should say to rebuild it first")
  endif()
  return()
endif()
if(NOT out MATCHES "01_ray_casting\\.cpp changed after this grader was built: rebuilding it first")
  message(FATAL_ERROR "after an edit of chapter 01, grade_02 \"[02.P]\" should say 01_ray_casting.cpp changed and rebuild")
endif()
if(out MATCHES "01\\.[0-9]")
  message(FATAL_ERROR "after chapter 01 was written, grade_02 \"[02.P]\" still names a chapter 01 exercise: it graded the old code")
endif()

# Nothing changed since: no rebuild.
grade(again)
if(out MATCHES "changed after this grader was built")
  message(FATAL_ERROR "nothing changed since the rebuild, yet grade_02 rebuilt again")
endif()
