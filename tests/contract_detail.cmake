# The two levels of a contract. A contract (chapters/NN_name/NN_name.hpp, or a stub's comment) says
# what a function returns; under it, a block of comment lines may say how, step by step, for an
# introductory course:
#
#   // EXERCISE 04.3: ... what it returns, its edge cases, its precision, an example ...
#   // DETAIL BEGIN: how, step by step (...)
#   // First turn n to the side dir leaves toward ...
#   // DETAIL END
#   point3 offset_ray_origin(const point3& p, const vec3& n, const vec3& dir);
#
# contract_detail(<text> <level> <where> <out> <count>) gives the text as handed out: level
# `behaviour` drops each block, markers and all; `detailed` keeps its lines and drops the two marker
# lines. <count> is the number of blocks. A block holds comment lines only (a code line inside one
# would vanish from the behaviour handout), and every BEGIN has its END: anything else is an error
# naming <where>, so a typo cannot hand out the steps by mistake.
#
# As a script it rewrites one file in place (tests/handout.cmake calls the function on every
# header and exercise of the handout):
#   cmake -D FILE=<file> [-D CONTRACTS=behaviour|detailed] -P tests/contract_detail.cmake
cmake_minimum_required(VERSION 3.22)  # the kit's own; a script has no policies otherwise

function(contract_detail text level where out count)
  if(NOT level MATCHES "^(behaviour|detailed)$")
    message(FATAL_ERROR "contracts: the level is behaviour or detailed, not '${level}'")
  endif()
  set(result "")
  set(rest "${text}")
  set(blocks 0)
  while(TRUE)
    string(FIND "${rest}" "// DETAIL BEGIN" begin)
    if(begin EQUAL -1)
      break()
    endif()
    # The marker's line: from the newline before it to the one after it.
    string(SUBSTRING "${rest}" 0 ${begin} before)
    string(FIND "${before}" "\n" line_start REVERSE)
    math(EXPR line_start "${line_start} + 1")
    math(EXPR indent_length "${begin} - ${line_start}")
    string(SUBSTRING "${rest}" ${line_start} ${indent_length} indent)
    if(NOT indent MATCHES "^[ \t]*$")
      message(FATAL_ERROR "contracts: ${where}: `// DETAIL BEGIN` must open a line of its own")
    endif()
    string(SUBSTRING "${rest}" 0 ${line_start} head)
    string(SUBSTRING "${rest}" ${line_start} -1 tail)
    string(FIND "${tail}" "\n" begin_eol)
    string(FIND "${tail}" "// DETAIL END" end)
    if(begin_eol EQUAL -1 OR end EQUAL -1)
      message(FATAL_ERROR "contracts: ${where}: a `// DETAIL BEGIN` without its `// DETAIL END`")
    endif()
    string(SUBSTRING "${tail}" 0 ${end} up_to_end)
    string(FIND "${up_to_end}" "\n" end_line_start REVERSE)
    math(EXPR end_line_start "${end_line_start} + 1")
    math(EXPR body_start "${begin_eol} + 1")
    if(end_line_start LESS body_start)
      message(FATAL_ERROR "contracts: ${where}: `// DETAIL END` must close a line of its own, after the BEGIN line")
    endif()
    math(EXPR body_length "${end_line_start} - ${body_start}")
    string(SUBSTRING "${tail}" ${body_start} ${body_length} body)
    math(EXPR indent_length "${end} - ${end_line_start}")
    string(SUBSTRING "${tail}" ${end_line_start} ${indent_length} indent)
    if(NOT indent MATCHES "^[ \t]*$")
      message(FATAL_ERROR "contracts: ${where}: `// DETAIL END` must open a line of its own")
    endif()
    string(FIND "${body}" "// DETAIL BEGIN" nested)
    if(NOT nested EQUAL -1)
      message(FATAL_ERROR "contracts: ${where}: a `// DETAIL BEGIN` inside another block (its END is missing)")
    endif()
    if(NOT body MATCHES "^([ \t]*//[^\n]*\n)*$")
      message(FATAL_ERROR "contracts: ${where}: a DETAIL block holds comment lines only, and this one holds:\n${body}")
    endif()
    # After the END line, newline included.
    string(SUBSTRING "${tail}" ${end} -1 after_end)
    string(FIND "${after_end}" "\n" end_eol)
    if(end_eol EQUAL -1)
      set(rest "")
    else()
      math(EXPR end_eol "${end_eol} + 1")
      string(SUBSTRING "${after_end}" ${end_eol} -1 rest)
    endif()
    if(level STREQUAL "detailed")
      string(APPEND result "${head}${body}")
    else()
      string(APPEND result "${head}")
    endif()
    math(EXPR blocks "${blocks} + 1")
  endwhile()
  string(FIND "${rest}" "// DETAIL END" stray)
  if(NOT stray EQUAL -1)
    message(FATAL_ERROR "contracts: ${where}: a `// DETAIL END` without its `// DETAIL BEGIN`")
  endif()
  string(APPEND result "${rest}")
  set(${out} "${result}" PARENT_SCOPE)
  set(${count} ${blocks} PARENT_SCOPE)
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  if(NOT FILE)
    message(FATAL_ERROR "contracts: say which file: -D FILE=<file> [-D CONTRACTS=behaviour|detailed]")
  endif()
  if(NOT DEFINED CONTRACTS)
    set(CONTRACTS behaviour)
  endif()
  file(READ "${FILE}" text)
  contract_detail("${text}" "${CONTRACTS}" "${FILE}" text blocks)
  file(WRITE "${FILE}" "${text}")
  message(STATUS "${FILE}: ${blocks} DETAIL block(s), handed out as ${CONTRACTS}")
endif()
