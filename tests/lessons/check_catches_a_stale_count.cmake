# lessons.check_catches_a_stale_count: the table check fails, naming the lesson's line, the row, the
# column and both values, when a count differs; passes when only a timed cell does; and fails when a
# lesson lacks a table the sweep writes; the same for a number of the prose marked as a cell.
#   cmake -D TOOL=lesson_tables -D WORK=dir -P check_catches_a_stale_count.cmake
file(MAKE_DIRECTORY "${WORK}")
set(code "<!-- table 99.t timed: ms -->\n| scene | tests/ray | ms |\n|---|---:|---:|\n| a | 4.5 | 10.0 ±3% |\n\nHow. Timed on X.\n<!-- end table -->\n")
file(WRITE "${WORK}/code.tables.md" "${code}")

function(expect lesson_text expected_rc expected_output)
  file(WRITE "${WORK}/README.md" "${lesson_text}")
  execute_process(COMMAND "${TOOL}" check "${WORK}/code.tables.md" "${WORK}/README.md"
    OUTPUT_VARIABLE out ERROR_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL expected_rc OR NOT out MATCHES "${expected_output}")
    message(FATAL_ERROR "expected exit ${expected_rc} and '${expected_output}', got ${rc}:\n${out}")
  endif()
endfunction()

expect("Intro.\n\n${code}" 0 "0 difference")
string(REPLACE "10.0 ±3%" "12.5 ±9%" timed_only "${code}")
expect("Intro.\n\n${timed_only}" 0 "0 difference")
string(REPLACE "| 4.5 |" "| 4.4 |" stale "${code}")
expect("Intro.\n\n${stale}" 1 "README.md:3: table 99.t, row 1 \\(a\\), column 'tests/ray': the lesson says 4.4, the code gives 4.5")
expect("Intro, no table.\n" 1 "has no '<!-- table 99.t -->'")

# A number of the prose marked as a cell: held to the code's like the table's own cells, a timed one
# refreshed but not compared, and a marker naming a row the table lacks is an error.
expect("The a row tests <!-- cell 99.t [a] tests/ray -->4.5<!-- /cell --> a ray.\n\n${code}" 0
  "1 cell\\(s\\) of prose against the code, 0 difference")
expect("It tests <!-- cell 99.t [a] tests/ray -->4.4<!-- /cell --> a ray.\n\n${code}" 1
  "README.md:1: the prose's cell 99.t \\[a\\] tests/ray: the lesson says 4.4, the code gives 4.5")
expect("In <!-- cell 99.t [a] ms -->9 ms<!-- /cell -->.\n\n${code}" 0 "0 difference")
expect("It tests <!-- cell 99.t [b] tests/ray -->4.5<!-- /cell --> a ray.\n\n${code}" 1
  "README.md:1: the prose's cell 99.t \\[b\\] tests/ray: table 99.t has no row \\[b\\]")
