# The two tracks: each chapter's exercise and solution build into their own object
# library, ex_NN and sol_NN, defining the same functions. A program or test for chapter N links one
# library per chapter 1..N.

foreach(chapter IN LISTS RT_CHAPTERS)
  string(SUBSTRING "${chapter}" 0 2 nn)
  # Grading builds a student's chapters one at a time (tests/grade.cmake): not part of `all` there.
  set(exercise_file "${RT_EXERCISES_DIR}/${chapter}.cpp")
  if(NOT EXISTS "${exercise_file}")
    # A submission without this chapter: a file that fails to compile with a message that says so,
    # so the chapter scores 0 and the others are graded.
    set(exercise_file "${CMAKE_BINARY_DIR}/missing_exercises/${chapter}.cpp")
    file(WRITE "${exercise_file}" "#error \"the submission has no ${chapter}.cpp\"\n")
    message(STATUS "${RT_EXERCISES_DIR} has no ${chapter}.cpp: chapter ${nn} scores 0")
  endif()
  add_library(ex_${nn} OBJECT "${exercise_file}")
  set_target_properties(ex_${nn} PROPERTIES EXCLUDE_FROM_ALL "${RT_GRADE}")
  target_link_libraries(ex_${nn} PUBLIC rt_common)
  # A stub's parameters are unused until the student writes the answer: no warning for that. (On the
  # file, whose options come after the target's -Wextra: clang lets the last of the two win.)
  set_source_files_properties("${exercise_file}" PROPERTIES COMPILE_OPTIONS
    "${RT_NO_UNUSED_PARAMETER_WARNING};${RT_STUDENT_ASSERTIONS}")
  if(RT_HAVE_SOLUTIONS)
    add_library(sol_${nn} OBJECT "${CMAKE_SOURCE_DIR}/solutions/${chapter}.cpp")
    target_link_libraries(sol_${nn} PUBLIC rt_common)
    if(RT_COVERAGE)
      # The coverage preset: branch counts of the solutions alone, unoptimised so that every branch
      # of the source stays a branch of the program. The counters are updated atomically: a render
      # runs the solutions on several threads, and plain increments from two threads can lose counts
      # or leave gcov a negative one, which gcovr refuses.
      target_compile_options(sol_${nn} PRIVATE -O0 --coverage -fprofile-update=atomic)
      target_link_options(sol_${nn} PUBLIC --coverage)
    endif()
  endif()
endforeach()

# rt_chapter_libraries(<out> <nn> <track>): the libraries a program or test of chapter <nn> links.
# track `figures`: the solutions of chapters 1..nn (the student's files in a handout).
# track `graded`: the student's chapter nn, and the solutions of the chapters before it when they
# exist, so a mistake in chapter 2 costs points in chapter 2 only.
# track `stubs`: the exercises of chapters 1..nn, as a handout without solutions builds them.
function(rt_chapter_libraries out nn track)
  set(libs "")
  foreach(chapter IN LISTS RT_CHAPTERS)
    string(SUBSTRING "${chapter}" 0 2 k)
    if(RT_HAVE_SOLUTIONS AND (track STREQUAL "figures" OR (track STREQUAL "graded" AND k LESS nn)))
      list(APPEND libs sol_${k})
    else()
      list(APPEND libs ex_${k})
    endif()
    if(k STREQUAL nn)
      break()
    endif()
  endforeach()
  set(${out} ${libs} PARENT_SCOPE)
endfunction()

# Each chapter's program renders its figure; the `figures` target renders them all. In the grade
# build the programs show the student's own picture: they link the graded track.
set(program_track figures)
if(RT_GRADE)
  set(program_track graded)
endif()
# The noisy chapters' figures need more samples than the programs' default of one per pixel, which
# shows their blur and penumbrae as grain.
set(RT_FIGURE_ARGS_05_soft_shadows --spp 16)
set(RT_FIGURE_ARGS_06_depth_of_field --spp 64)
set(figure_files "")
foreach(chapter IN LISTS RT_CHAPTERS)
  string(SUBSTRING "${chapter}" 0 2 nn)
  add_executable(${chapter} "${CMAKE_SOURCE_DIR}/chapters/${chapter}/main.cpp")
  set_target_properties(${chapter} PROPERTIES EXCLUDE_FROM_ALL "${RT_GRADE}")
  rt_chapter_libraries(libs ${nn} ${program_track})
  # From chapter 07 on, the figures are the kit's generated scenes (common/scenes/nff_generators).
  target_link_libraries(${chapter} PRIVATE ${libs} nff_generators)
  set(figure "${RT_FIGURES_DIR}/${chapter}.png")
  # On the terminal (Ninja's console pool, one render at a time, each on every core): Ninja would
  # otherwise hold a render's progress line until the render ends.
  add_custom_command(OUTPUT "${figure}"
    COMMAND ${chapter} --out "${figure}" ${RT_FIGURE_ARGS_${chapter}}
    DEPENDS ${chapter}
    COMMENT "Rendering ${figure}"
    USES_TERMINAL
    VERBATIM)
  list(APPEND figure_files "${figure}")
endforeach()
add_custom_target(figures DEPENDS ${figure_files})

# The figures the README and the lessons show, small enough to keep in the repository and large
# enough to judge: `cmake --build build/release --target readme_figures` rewrites
# chapters/NN_name/figure.png (after a change to a figure; look at them before committing).
set(RT_README_SIZE_05_soft_shadows --width 600 --height 240)
set(readme_commands "")
foreach(chapter IN LISTS RT_CHAPTERS)
  set(size --width 480 --height 270)
  if(DEFINED RT_README_SIZE_${chapter})
    set(size ${RT_README_SIZE_${chapter}})
  endif()
  list(APPEND readme_commands COMMAND ${chapter} --out "${CMAKE_SOURCE_DIR}/chapters/${chapter}/figure.png"
    ${RT_FIGURE_ARGS_${chapter}} ${size})
endforeach()
add_custom_target(readme_figures ${readme_commands} COMMENT "Rendering chapters/NN_name/figure.png" VERBATIM)
# The scene generator the README points instructors to comes with the figures.
add_dependencies(figures nff_generate)

# The speed/accuracy tables: `cmake --build <build> --target trade` runs every program's --sweep
# into build/trade/NN_name.csv and, when gnuplot is installed (optional: nothing else needs it;
# looked for when the target runs, so installing it later is enough), draws each as
# build/trade/NN_name.png.
set(RT_TRADE_DIR "${CMAKE_SOURCE_DIR}/build/trade" CACHE PATH "Where the trade target writes its tables and plots")
set(trade_files "")
foreach(chapter IN LISTS RT_CHAPTERS)
  set(csv "${RT_TRADE_DIR}/${chapter}.csv")
  # A chapter whose table is not a cost-error curve draws it with its own script.
  set(plot_script "${CMAKE_SOURCE_DIR}/common/trade_plot.gnuplot")
  if(EXISTS "${CMAKE_SOURCE_DIR}/chapters/${chapter}/trade_plot.gnuplot")
    set(plot_script "${CMAKE_SOURCE_DIR}/chapters/${chapter}/trade_plot.gnuplot")
  endif()
  set(png "${RT_TRADE_DIR}/${chapter}.png")
  add_custom_command(OUTPUT "${csv}"
    BYPRODUCTS "${RT_TRADE_DIR}/${chapter}.tables.md"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${RT_TRADE_DIR}"
    COMMAND ${chapter} --sweep --csv "${csv}"
    COMMAND "${CMAKE_COMMAND}" -D "SCRIPT=${plot_script}"
      "-D" "ARGS=-e|csv='${csv}'|-e|png='${png}'|-e|title='${chapter}'"
      -P "${CMAKE_SOURCE_DIR}/common/plot_if_gnuplot.cmake"
    DEPENDS ${chapter} "${plot_script}"
    COMMENT "Measuring ${chapter}'s trade into ${csv}"
    USES_TERMINAL
    VERBATIM)
  list(APPEND trade_files "${csv}")
endforeach()
add_custom_target(trade DEPENDS ${trade_files})

# The lessons' measured tables are the sweeps' own (common/lesson_table.hpp): after `trade`,
# `cmake --build <build> --target lesson_tables_refresh` pastes each chapter's NN_name.tables.md into its
# lesson between the table's markers, and copies its plot to chapters/NN_name/trade.png. The test lessons.tables_NN holds every column but the timed
# ones to the code. Look at the diff before committing: the timed columns move with the machine.
add_executable(lesson_tables "${CMAKE_SOURCE_DIR}/tests/lessons/lesson_tables.cpp")
set_target_properties(lesson_tables PROPERTIES EXCLUDE_FROM_ALL ON)
set(lesson_table_files "")
foreach(chapter IN LISTS RT_CHAPTERS)
  list(APPEND lesson_table_files "${RT_TRADE_DIR}/${chapter}.tables.md")
endforeach()
string(REPLACE ";" "," chapter_names "${RT_CHAPTERS}")
add_custom_target(lesson_tables_refresh
  COMMAND lesson_tables refresh ${lesson_table_files} --kit "${CMAKE_SOURCE_DIR}"
  COMMAND "${CMAKE_COMMAND}" -D "TRADE_DIR=${RT_TRADE_DIR}" -D "KIT=${CMAKE_SOURCE_DIR}" -D "CHAPTERS=${chapter_names}"
    -P "${CMAKE_SOURCE_DIR}/chapters/lesson_plots.cmake"
  DEPENDS trade lesson_tables
  COMMENT "Pasting the sweeps' tables and plots into the lessons"
  VERBATIM)

# The path of one ray, drawn (chapters/programs/ray_trip.svg) from the numbered list of
# chapters/programs/README.md: `--target trip_map_refresh` redraws it after an edit of the list; the
# test lessons.ray_trip_map_current fails while the drawing is not the list's.
add_executable(trip_map "${CMAKE_SOURCE_DIR}/tests/lessons/trip_map.cpp")
add_custom_target(trip_map_refresh
  COMMAND trip_map write "${CMAKE_SOURCE_DIR}/chapters/programs/README.md"
    "${CMAKE_SOURCE_DIR}/chapters/programs/ray_trip.svg"
  DEPENDS trip_map
  COMMENT "Drawing chapters/programs/ray_trip.svg from the README's list of hops"
  VERBATIM)

# The kit's NFF scenes (common/scenes/) rendered by every program from chapter 02 on, each with its
# chapter's features, and by chapter 04's classic NFF mode: `cmake --build <build> --target scenes`
# writes build/scenes/NN_name-SCENE.png (04_shadow_feelers-classic-SCENE.png for the classic mode).
set(RT_SCENES_DIR "${CMAKE_SOURCE_DIR}/build/scenes" CACHE PATH "Where the scenes target writes its pictures")
file(GLOB kit_scene_files "${CMAKE_SOURCE_DIR}/common/scenes/*.nff")
set(scene_pictures "")
foreach(chapter IN LISTS RT_CHAPTERS)
  if(chapter MATCHES "^01_")
    continue()  # chapter 01's discs and planes are not NFF's shapes
  endif()
  foreach(scene_file IN LISTS kit_scene_files)
    get_filename_component(scene "${scene_file}" NAME_WE)
    set(modes "plain")
    if(chapter STREQUAL "04_shadow_feelers")
      list(APPEND modes "classic")
    endif()
    foreach(mode IN LISTS modes)
      set(picture "${RT_SCENES_DIR}/${chapter}-${scene}.png")
      set(args ${RT_FIGURE_ARGS_${chapter}})
      if(mode STREQUAL "classic")
        set(picture "${RT_SCENES_DIR}/${chapter}-classic-${scene}.png")
        set(args --classic)
      endif()
      add_custom_command(OUTPUT "${picture}"
        COMMAND "${CMAKE_COMMAND}" -E make_directory "${RT_SCENES_DIR}"
        COMMAND ${chapter} --scene "${scene_file}" --out "${picture}" ${args}
        DEPENDS ${chapter} "${scene_file}"
        COMMENT "Rendering ${picture}"
        VERBATIM)
      list(APPEND scene_pictures "${picture}")
    endforeach()
  endforeach()
endforeach()
add_custom_target(scenes DEPENDS ${scene_pictures})
include("${CMAKE_SOURCE_DIR}/chapters/benchmark/benchmark.cmake")
