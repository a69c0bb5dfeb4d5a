# The line under a lesson's title that names every earlier exercise the chapter's graded cases run:
# made here, held to the cases by earlier_exercises.cmake, trimmed of solved chapters by handout.cmake.

# The line for the exercises given (in order), or "" when there are none:
# "**Before you start:** this chapter's graded cases also run your 01.1, 02.2 and 02.5. <!-- ... -->"
function(rt_earlier_line out)
  set(listed ${ARGN})
  set(line "")
  if(listed)
    list(POP_BACK listed final)
    string(JOIN ", " words ${listed})
    if(words)
      string(APPEND words " and ")
    endif()
    set(line "**Before you start:** this chapter's graded cases also run your ${words}${final}. <!-- earlier exercises -->")
  endif()
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

# The exercises a lesson's line names, as a list (empty for a text without the line).
function(rt_earlier_listed out text)
  set(listed "")
  if(text MATCHES "also run your ([^<]*)\\. <!-- earlier exercises -->")
    string(REPLACE " and " ", " listed "${CMAKE_MATCH_1}")
    string(REPLACE ", " ";" listed "${listed}")
  endif()
  set(${out} "${listed}" PARENT_SCOPE)
endfunction()
