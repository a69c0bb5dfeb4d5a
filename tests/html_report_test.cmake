# The HTML report of a grading run, as a reader sees it: a chapter 01 whose image is upside down
# graded (the mutant 01_y_flipped: the picture case fails with its three images), written as a page
# by grade_report, which must show the points, every failure, and the expected, actual and
# difference images embedded in it. When chromium is installed, a headless chromium loads the page and takes a
# screenshot (WORK/report.png), which must not be blank.
#   cmake -D GRADER=<grade_mutant_01_y_flipped> -D REPORT=<grade_report> -D WORK=<folder> -P html_report_test.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${GRADER}" --results "${WORK}/01.results" --artifacts "${WORK}/pictures"
  OUTPUT_QUIET ERROR_QUIET)
execute_process(COMMAND "${REPORT}" --html "${WORK}/report.html" --json "${WORK}/results.json" --title "y flipped" "${WORK}/01.results"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/report.html")
  message(FATAL_ERROR "grade_report wrote no report (${rc})")
endif()
file(READ "${WORK}/report.html" html)
file(STRINGS "${WORK}/01.results" cases)
set(n 0)
foreach(c IN LISTS cases)
  if(c MATCHES "^[^\t]+\t([0-9]+)\t([0-9]+)\t" AND NOT CMAKE_MATCH_1 EQUAL CMAKE_MATCH_2)
    math(EXPR n "${n} + 1")
  endif()
endforeach()
string(REGEX MATCHALL "<tr class=\"fail\">" failed "${html}")
list(LENGTH failed f)
# (A data URI holds a ';', which would split a CMake list: match up to it, then the PNG's signature.)
string(REGEX MATCHALL "<img alt=\"(expected|actual|difference)\" src=\"data:image/png" images "${html}")
string(REGEX MATCHALL "base64,iVBORw0KGgo[A-Za-z0-9+/]+=*\"><figcaption>" pngs "${html}")
list(LENGTH pngs p)
list(LENGTH images i)
string(REGEX MATCHALL "<img" all_images "${html}")
list(LENGTH all_images a)
if(NOT html MATCHES "<h1>y flipped: [0-9]+ / [1-9][0-9]* points</h1>" OR n EQUAL 0 OR NOT f EQUAL n OR NOT i EQUAL 3 OR NOT p EQUAL 3 OR NOT a EQUAL 3)
  message(FATAL_ERROR "the report should show the points, ${n} failed cases (it shows ${f}) and the picture case's "
    "three images embedded (it has ${i} of ${a})")
endif()
# Gradescope shows the student the same images: the picture case's output is HTML with them embedded.
file(READ "${WORK}/results.json" json)
string(REGEX MATCHALL "<img alt=\\\\\"(expected|actual|difference)\\\\\" src=\\\\\"data:image/png" json_images "${json}")
list(LENGTH json_images j)
if(NOT j EQUAL 3 OR NOT json MATCHES "\"output_format\": \"html\"")
  message(FATAL_ERROR "results.json should give the picture case's output as HTML with its three images (${j}):\n${json}")
endif()
find_program(CHROMIUM NAMES chromium chromium-browser NO_CACHE)
if(CHROMIUM)
  execute_process(COMMAND "${CHROMIUM}" --headless --no-sandbox --disable-gpu --hide-scrollbars
      --window-size=1280,2400 "--screenshot=${WORK}/report.png" "file://${WORK}/report.html"
    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
  file(SIZE "${WORK}/report.png" bytes)
  if(NOT rc EQUAL 0 OR bytes LESS 20000)
    message(FATAL_ERROR "chromium did not render the report (${rc}, ${bytes} bytes)")
  endif()
  message(STATUS "chromium rendered the report: ${WORK}/report.png")
else()
  message(STATUS "chromium is not installed: the page was checked, not rendered")
endif()
