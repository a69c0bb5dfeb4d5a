# "Adding a chapter" (chapters/README.md) followed on a scratch chapter, 11_scratch, in a scratch
# copy of the recipe: a folder with only a lesson and a program lacks hints.md and CLAUSES.md (the
# two files the recipe once left out), and the check names them; with every file of the table
# written, the check passes; a chapter that adds a structure needs its diagnosis file too.
#   cmake -D KIT=<kit> -D WORK=<scratch dir> -P scratch_chapter_test.cmake
cmake_minimum_required(VERSION 3.25)
set(check "${KIT}/tests/chapters/chapter_files.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/chapters/11_scratch")
file(COPY_FILE "${KIT}/chapters/README.md" "${WORK}/chapters/README.md")
file(WRITE "${WORK}/chapters/11_scratch/README.md" "# Scratch\n")
file(WRITE "${WORK}/chapters/11_scratch/main.cpp" "int main() {}\n")

function(run_check expect_fail)
  execute_process(COMMAND "${CMAKE_COMMAND}" -D "KIT=${WORK}" -D CHAPTERS=11_scratch ${ARGN} -P "${check}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(said "${out}${err}" PARENT_SCOPE)
  if(expect_fail AND rc EQUAL 0)
    message(FATAL_ERROR "the check passed a chapter that lacks files:\n${out}${err}")
  elseif(NOT expect_fail AND NOT rc EQUAL 0)
    message(FATAL_ERROR "the check failed a chapter that has every file:\n${out}${err}")
  endif()
endfunction()

run_check(ON)
foreach(lacking "chapters/11_scratch/hints.md" "tests/ch11/CLAUSES.md" "solutions/11_scratch.cpp"
                "grader.ch11.clauses" "hints.three_tiers_for_every_exercise")
  string(FIND "${said}" "${lacking}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the check of a chapter with only README.md and main.cpp does not name ${lacking}:\n${said}")
  endif()
endforeach()
string(FIND "${said}" "_suspect.hpp" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the check asks a chapter that adds no structure for a diagnosis file:\n${said}")
endif()

run_check(OFF -D FOLLOW=ON)
run_check(OFF)

file(WRITE "${WORK}/chapters/11_scratch/figure.hpp" "inline Structures structures()\n")
run_check(ON)
string(FIND "${said}" "tests/ch11/*_suspect.hpp" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the check of a chapter that adds a structure does not ask for its diagnosis file:\n${said}")
endif()
message(STATUS "the recipe, followed on 11_scratch, passes its check; each file left out is named")
