# A class of three graded as a batch (grade_batch.cmake) on chapters 01 and 02, as an instructor
# would: alice hands in the solutions, bob forgets chapter 02's file, carol hands in chapter 01
# untouched and a chapter 02 that does not compile. The batch must grade all three to a complete
# gradebook; bob's and carol's chapter 02 and carol's chapter 01 must each be one line, worth the
# whole chapter, in results.json, junit.xml and the class page; and a second batch in the same
# build folder grades the files as they are now.
#   cmake -D SOURCE_DIR=<the kit> -D WORK=<a scratch folder> -P batch_test.cmake
file(REMOVE_RECURSE "${WORK}/class")
set(class "${WORK}/class")
file(MAKE_DIRECTORY "${class}/alice" "${class}/bob" "${class}/carol")
file(COPY "${SOURCE_DIR}/solutions/01_ray_casting.cpp" "${SOURCE_DIR}/solutions/02_spheres_triangles.cpp"
  DESTINATION "${class}/alice")
file(COPY "${SOURCE_DIR}/solutions/01_ray_casting.cpp" DESTINATION "${class}/bob")
file(COPY "${SOURCE_DIR}/exercises/01_ray_casting.cpp" DESTINATION "${class}/carol")
file(READ "${SOURCE_DIR}/exercises/02_spheres_triangles.cpp" text)
file(WRITE "${class}/carol/02_spheres_triangles.cpp" "${text}\nint carol_forgot_the_semicolon = 1\n")

execute_process(COMMAND "${CMAKE_COMMAND}" -D "SUBMISSIONS=${class}" -D "BUILD_DIR=${WORK}/build" -D "CHAPTERS=01;02"
    -P "${SOURCE_DIR}/tests/grade_batch.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
function(fail why)
  message(FATAL_ERROR "${why}\n--- the batch said:\n${out}")
endfunction()
if(NOT rc EQUAL 0)
  fail("the batch exited with ${rc}")
endif()
foreach(student alice bob carol)
  if(NOT out MATCHES "${student}: [0-9]+ / [0-9]+")
    fail("no total printed for ${student}")
  endif()
endforeach()
string(REGEX MATCH "alice: ([0-9]+) / ([0-9]+)" alice "${out}")
if(NOT CMAKE_MATCH_1 EQUAL CMAKE_MATCH_2)
  fail("alice handed in the solutions but scored ${CMAKE_MATCH_1} / ${CMAKE_MATCH_2}")
endif()
set(maximum ${CMAKE_MATCH_2})
foreach(student bob carol)
  string(REGEX MATCH "${student}: [0-9]+ / ([0-9]+)" line "${out}")
  if(NOT CMAKE_MATCH_1 EQUAL maximum)
    fail("${student}'s maximum is ${CMAKE_MATCH_1}, alice's ${maximum}: a chapter's cases went missing")
  endif()
endforeach()

file(STRINGS "${WORK}/build/gradebook.csv" book)
list(LENGTH book rows)
list(GET book 1 max_row)
if(NOT rows EQUAL 5 OR NOT max_row MATCHES "^\"\\(maximum\\)\",[0-9]+,[1-9][0-9]*,${maximum}$")
  fail("the gradebook should be a header, a row of maxima and three students:\n${book}")
endif()
list(GET book 3 bob_row)
if(NOT bob_row MATCHES "^\"bob\",[0-9]+,0,[0-9]+$")
  fail("bob has no chapter 02 file, so 0 there: ${bob_row}")
endif()

# Chapter 02's maximum, from alice's cases.
file(READ "${WORK}/build/students/alice/results.json" alice_json)
string(REGEX MATCHALL "\"number\": \"02\\.[0-9A-Z]+\", \"score\": [0-9]+, \"max_score\": [0-9]+" alice_cases "${alice_json}")
set(chapter_02_max 0)
foreach(c IN LISTS alice_cases)
  string(REGEX MATCH "[0-9]+$" points "${c}")
  math(EXPR chapter_02_max "${chapter_02_max} + ${points}")
endforeach()
if(chapter_02_max EQUAL 0)
  fail("alice's results.json lists no chapter 02 case")
endif()
# bob's missing file and carol's compile error are one line each, worth the whole chapter, in
# results.json and in junit.xml; so is carol's untouched chapter 01.
foreach(student bob carol)
  file(READ "${WORK}/build/students/${student}/results.json" json)
  string(REGEX MATCHALL "\"number\": \"02[^\"]*\"" lines "${json}")
  list(LENGTH lines n)
  if(NOT n EQUAL 1 OR NOT json MATCHES "\"number\": \"02\", \"score\": 0, \"max_score\": ${chapter_02_max},")
    fail("${student}'s results.json should give chapter 02 as one line at 0 of ${chapter_02_max}, not ${n} lines:\n${json}")
  endif()
  file(READ "${WORK}/build/students/${student}/junit.xml" junit)
  if(NOT junit MATCHES "testsuite name=\"chapter 02\" tests=\"1\" failures=\"1\"")
    fail("${student}'s junit.xml should hold chapter 02 as one failed case:\n${junit}")
  endif()
endforeach()
if(NOT json MATCHES "chapter 02 does not compile" OR NOT json MATCHES "02_spheres_triangles.cpp:[0-9]+:[0-9]+: error")
  fail("carol's results should say her chapter 02 does not compile, with the compiler's error")
endif()
# The compiler's words for it, semicolon and all: gcc's "expected ',' or ';' at end of input" (with
# curly quotes in a UTF-8 locale), clang's "expected ';' after top level declarator".
if(NOT json MATCHES "error: expected [^\\]*;")
  fail("carol's results should give the compiler's error whole, its semicolon included")
endif()
if(json MATCHES "${class}")
  fail("carol's results carry the grading machine's paths")
endif()
string(REGEX MATCHALL "\"number\": \"01[^\"]*\"" lines "${json}")
list(LENGTH lines n)
if(NOT n EQUAL 1 OR NOT json MATCHES "chapter 01 is still the handed-out stubs")
  fail("carol's chapter 01 is the handed-out stubs: one line saying so, not ${n}")
endif()
file(READ "${WORK}/build/students/bob/results.json" json)
if(NOT json MATCHES "the submission has no 02_spheres_triangles.cpp")
  fail("bob's results should say his chapter 02 file is missing")
endif()
file(READ "${WORK}/build/class.html" page)
foreach(student alice bob carol)
  if(NOT page MATCHES "href=\"students/${student}/report.html\">${student}</a></td><td>[0-9]+ / ${maximum}<"
     OR NOT EXISTS "${WORK}/build/students/${student}/report.html")
    fail("class.html should link ${student}'s report with their total")
  endif()
endforeach()
# Each chapter's cell says what went wrong there.
if(NOT page MATCHES ">bob</a>.*no file.*>carol</a>.*untouched.*does not compile")
  fail("class.html should flag bob's missing file, carol's untouched chapter 01 and her compile error:\n${page}")
endif()
message(STATUS "a class of three: ${out}")

# A student's grader run after an edit rebuilds itself first: the build folder now grades carol's
# files (the last graded); her chapter 01, the untouched stubs, becomes the solution, and grading
# 01.2 alone must rebuild and score it in full, not grade the stale program.
file(READ "${SOURCE_DIR}/solutions/01_ray_casting.cpp" solution)
file(WRITE "${class}/carol/01_ray_casting.cpp" "${solution}")
file(GLOB grader LIST_DIRECTORIES false "${WORK}/build/tests/grade_01" "${WORK}/build/tests/*/grade_01.exe" "${WORK}/build/tests/grade_01.exe")
execute_process(COMMAND ${grader} "[01.2]" RESULT_VARIABLE rc OUTPUT_VARIABLE regrade ERROR_VARIABLE regrade)
if(WIN32)
  if(NOT rc EQUAL 2 OR NOT regrade MATCHES "changed after this grader was built")
    fail("grade_01 after an edit should say to rebuild it first (${rc}):\n${regrade}")
  endif()
elseif(NOT rc EQUAL 0 OR NOT regrade MATCHES "changed after this grader was built: rebuilding it first"
       OR NOT regrade MATCHES "01\\.2 +19 / 19")
  fail("grade_01 after an edit should rebuild and give 01.2 full points (${rc}):\n${regrade}")
endif()

# The batch again, carol's chapter 01 the handed-out stubs once more, copied with their old file
# times (as a submission unpacked from an archive keeps them): older than the object the edit above
# left, so a build that trusted times would grade the solution. She must get the stubs' line again.
# Carol alone this time, in the same folder (the others would only rebuild to the same grades).
file(REMOVE_RECURSE "${class}/alice" "${class}/bob")
file(REMOVE "${class}/carol/01_ray_casting.cpp")
file(COPY "${SOURCE_DIR}/exercises/01_ray_casting.cpp" DESTINATION "${class}/carol")
execute_process(COMMAND "${CMAKE_COMMAND}" -D "SUBMISSIONS=${class}" -D "BUILD_DIR=${WORK}/build" -D "CHAPTERS=01;02"
    -P "${SOURCE_DIR}/tests/grade_batch.cmake"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
file(READ "${WORK}/build/students/carol/results.json" json)
if(NOT rc EQUAL 0 OR NOT json MATCHES "chapter 01 is still the handed-out stubs")
  fail("a second batch should grade carol's chapter 01 as the stubs again, not the program an earlier run built")
endif()
