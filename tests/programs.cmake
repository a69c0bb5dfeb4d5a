# The chapter programs as a user meets them: bad input gets one line naming the problem and exit
# status 2; a small render exits 0 and prints its stats.
function(rt_expect_exit name program status match)
  string(JOIN "|" args ${ARGN})
  add_test(NAME programs.${name}
    COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:${program}>" -D "ARGS=${args}" -D "STATUS=${status}"
      -D "MATCH=${match}" -P "${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake")
  set_tests_properties(programs.${name} PROPERTIES LABELS "programs")
endfunction()

foreach(chapter IN LISTS RT_CHAPTERS)
  rt_expect_exit(${chapter}.unknown_flag ${chapter} 2 "unknown option '--colour'" --colour)
  rt_expect_exit(${chapter}.zero_width ${chapter} 2 "--width must be between 1 and" --width 0)
  rt_expect_exit(${chapter}.width_not_a_number ${chapter} 2 "--width takes a whole number, got '12px'" --width 12px)
  rt_expect_exit(${chapter}.missing_value ${chapter} 2 "--height needs a value" --height)
  rt_expect_exit(${chapter}.help ${chapter} 0 "usage: ${chapter}" --help)
  rt_expect_exit(${chapter}.small_render_stats ${chapter} 0 "rays_primary=600\n"
    --width 30 --height 20 --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}.png" --stats)
endforeach()
rt_expect_exit(01_ray_casting.fov_180 01_ray_casting 2 "--fov must lie strictly between 0 and 180, got 180" --fov 180)
rt_expect_exit(01_ray_casting.fov_nan 01_ray_casting 2 "--fov takes a finite number, got 'nan'" --fov nan)
rt_expect_exit(01_ray_casting.unwritable_png 01_ray_casting 2 "cannot write the PNG file"
  --width 4 --height 4 --out /proc/no/such/folder/x.png)
rt_expect_exit(02_spheres_triangles.unknown_triangle_test 02_spheres_triangles 2 "--triangle" --triangle bogus)
rt_expect_exit(02_spheres_triangles.probes_too_few 02_spheres_triangles 2 "--probes must be between 1000 and" --probes 10)
