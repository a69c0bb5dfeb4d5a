# The ground floor stands alone: no file of common/ includes a chapter's header (nor the programs'
# shared code, the benchmark's, the solutions' or the exercises'), so a chapter can build on common/
# and never the other way round.
# cmake -DKIT=<kit folder> -P ground_floor.cmake
file(GLOB_RECURSE files "${KIT}/common/*.hpp" "${KIT}/common/*.cpp")
set(found "")
foreach(file IN LISTS files)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<](chapters/)?[0-9][0-9]_|^[ \t]*#[ \t]*include[ \t]*[\"<](benchmark|programs|solutions|exercises)/")
  foreach(line IN LISTS lines)
    file(RELATIVE_PATH name "${KIT}" "${file}")
    string(APPEND found "\n  ${name}: ${line}")
  endforeach()
endforeach()
list(LENGTH files count)
if(found)
  message(FATAL_ERROR "common/ includes from the chapters:${found}")
endif()
message(STATUS "${count} files of common/ include nothing from the chapters")
