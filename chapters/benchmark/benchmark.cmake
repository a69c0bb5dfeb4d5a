# The benchmark (chapters/benchmark/): every structure of chapters 07-10 beside Embree 3 on the
# same rays. Embree is optional: found with find_package when libembree-dev is installed, and
# nothing else in the kit needs it; without it the benchmark measures the kit's structures and says
# it skipped Embree. `cmake --workflow --preset bench` builds it in release and runs it
# (bench_results), writing build/bench/results.csv, results.md and plots when gnuplot is there.
find_package(embree 3 QUIET)
set(bench_sources "${CMAKE_SOURCE_DIR}/chapters/benchmark/main.cpp")
if(embree_FOUND)
  list(APPEND bench_sources "${CMAKE_SOURCE_DIR}/chapters/benchmark/embree_accel.cpp")
  message(STATUS "Embree ${embree_VERSION} found: the benchmark measures it")
else()
  list(APPEND bench_sources "${CMAKE_SOURCE_DIR}/chapters/benchmark/embree_absent.cpp")
  message(STATUS "Embree not found: the benchmark measures the kit's structures only (apt-get install libembree-dev)")
endif()
add_executable(benchmark ${bench_sources})
set_target_properties(benchmark PROPERTIES EXCLUDE_FROM_ALL "${RT_GRADE}")
rt_chapter_libraries(libs 10 figures)
target_link_libraries(benchmark PRIVATE ${libs} nff_generators)
if(embree_FOUND)
  target_link_libraries(benchmark PRIVATE embree)
endif()

set(RT_BENCH_DIR "${CMAKE_BINARY_DIR}" CACHE PATH "Where bench_results writes results.csv and the tables")
add_custom_target(bench_results
  COMMAND benchmark --out-dir "${RT_BENCH_DIR}" --classic
  COMMAND "${CMAKE_COMMAND}" -D "SCRIPT=${CMAKE_SOURCE_DIR}/chapters/benchmark/bench_plot.gnuplot"
    "-D" "ARGS=-e|dir='${RT_BENCH_DIR}'" -P "${CMAKE_SOURCE_DIR}/common/plot_if_gnuplot.cmake"
  DEPENDS benchmark
  COMMENT "Benchmarking every structure (and Embree, when found) into ${RT_BENCH_DIR}/results.csv"
  USES_TERMINAL
  VERBATIM)
