# lessons.tables_NN: runs chapter NN's sweep once (--repeat 1: the timed columns are not compared)
# and holds the lesson's tables to what it writes.
#   cmake -D PROGRAM=... -D TOOL=lesson_tables -D LESSON=chapters/NN/README.md -D WORK=dir -P check_tables.cmake
get_filename_component(name "${PROGRAM}" NAME_WE)
file(MAKE_DIRECTORY "${WORK}")
set(csv "${WORK}/${name}.csv")
execute_process(COMMAND "${PROGRAM}" --sweep --repeat 1 --csv "${csv}"
  OUTPUT_FILE "${WORK}/${name}.sweep.log" ERROR_FILE "${WORK}/${name}.sweep.log" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  file(READ "${WORK}/${name}.sweep.log" log)
  message(FATAL_ERROR "${name} --sweep failed (${rc}):\n${log}")
endif()
execute_process(COMMAND "${TOOL}" check "${WORK}/${name}.tables.md" "${LESSON}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${LESSON}'s tables differ from what ${name} computes now: if the code changed on purpose, "
    "refresh them (cmake --build build/release --target lesson_tables_refresh) and look at the diff")
endif()
