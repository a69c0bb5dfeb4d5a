# Which open exercises a course assigns (RT_OPEN_EXERCISES: all, none, or a list such as
# "08.4;10.7"). An open exercise's graded cases live in a file of their own, tests/chNN/open_*.cpp,
# whose first line names it ("// EXERCISE 10.7 (open): ..."); an open exercise not assigned leaves
# its file out of the grader, so its cases are neither run nor counted in any total.
# Used by tests/CMakeLists.txt (the graders), handout.cmake, grade_batch.cmake and the Gradescope
# package, so the choice is read the same way everywhere.
cmake_policy(VERSION 3.22)  # IN_LIST and ZIP_LISTS in the scripts (cmake -P) that include this too

# rt_open_case_files(<out_numbers> <out_files> <tests_dir>): every open exercise's number and its
# case file, in the same order.
function(rt_open_case_files out_numbers out_files tests_dir)
  file(GLOB files "${tests_dir}/ch[0-9][0-9]/open_*.cpp")
  list(SORT files)
  set(numbers "")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" first LIMIT_COUNT 1)
    if(NOT first MATCHES "^// EXERCISE ([0-9][0-9]\\.[0-9]+) \\(open\\)")
      message(FATAL_ERROR "${f}:1: an open exercise's case file opens with `// EXERCISE NN.k (open): ...`, not '${first}'")
    endif()
    list(APPEND numbers "${CMAKE_MATCH_1}")
  endforeach()
  set(${out_numbers} "${numbers}" PARENT_SCOPE)
  set(${out_files} "${files}" PARENT_SCOPE)
endfunction()

# rt_open_assigned(<out> <choice> <tests_dir> <who>): the open exercises `choice` assigns, checked:
# all (the default, also for an empty choice), none, or a list of the kit's open exercises. A
# choice that names anything else stops `who` (the caller's name for the message).
function(rt_open_assigned out choice tests_dir who)
  rt_open_case_files(numbers files "${tests_dir}")
  string(JOIN ", " known ${numbers})
  if(choice STREQUAL "" OR choice STREQUAL "all")
    set(${out} "${numbers}" PARENT_SCOPE)
    return()
  endif()
  if(choice STREQUAL "none")
    set(${out} "" PARENT_SCOPE)
    return()
  endif()
  foreach(n IN LISTS choice)
    if(NOT n IN_LIST numbers)
      message(FATAL_ERROR "${who}: the open exercises assigned are all, none, or a list of ${known} (\"${numbers}\"); '${n}' is not one of them")
    endif()
  endforeach()
  set(${out} "${choice}" PARENT_SCOPE)
endfunction()

# rt_open_unassigned_files(<out> <choice> <tests_dir> <who>): the case files of the open exercises
# `choice` does not assign.
function(rt_open_unassigned_files out choice tests_dir who)
  rt_open_assigned(assigned "${choice}" "${tests_dir}" "${who}")
  rt_open_case_files(numbers files "${tests_dir}")
  set(left_out "")
  foreach(n f IN ZIP_LISTS numbers files)
    if(NOT n IN_LIST assigned)
      list(APPEND left_out "${f}")
    endif()
  endforeach()
  set(${out} "${left_out}" PARENT_SCOPE)
endfunction()
