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
rt_expect_exit(03_reflection_refraction.unknown_fresnel 03_reflection_refraction 2
  "--fresnel takes exact or schlick, got 'fuzzy'" --fresnel fuzzy)
rt_expect_exit(03_reflection_refraction.depth_too_deep 03_reflection_refraction 2
  "--depth must be between 0 and 64, got 65" --depth 65)
rt_expect_exit(03_reflection_refraction.min_weight_zero 03_reflection_refraction 2
  "--min-weight must lie strictly between 0 and 1, got 0" --min-weight 0)
rt_expect_exit(03_reflection_refraction.secondary_rays_counted 03_reflection_refraction 0
  "rays_reflected=[1-9][0-9]*\nrays_refracted=[1-9]" --width 30 --height 20 --depth 2
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/03_reflection_refraction_depth2.png" --stats)
rt_expect_exit(04_shadow_feelers.unknown_offset 04_shadow_feelers 2
  "--offset takes none, t-min, normal or robust, got 'epsilon'" --offset epsilon)
rt_expect_exit(04_shadow_feelers.unknown_feelers 04_shadow_feelers 2
  "--feelers takes any-hit, closest-hit or off, got 'all'" --feelers all)
rt_expect_exit(04_shadow_feelers.scale_zero 04_shadow_feelers 2 "--scale must lie strictly between 0 and" --scale 0)
rt_expect_exit(04_shadow_feelers.scale_not_finite 04_shadow_feelers 2 "--scale takes a finite number, got 'inf'" --scale inf)
rt_expect_exit(04_shadow_feelers.probes_too_few 04_shadow_feelers 2 "--probes must be between 1000 and" --probes 10)
rt_expect_exit(04_shadow_feelers.shadow_rays_counted 04_shadow_feelers 0
  "rays_shadow=[1-9][0-9]*\n" --width 30 --height 20
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/04_shadow_feelers_feelers.png" --stats)
rt_expect_exit(04_shadow_feelers.no_feelers_when_off 04_shadow_feelers 0
  "rays_shadow=0\n" --width 30 --height 20 --feelers off
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/04_shadow_feelers_off.png" --stats)
rt_expect_exit(06_depth_of_field.negative_aperture 06_depth_of_field 2
  "--aperture must be 0 \\(a pinhole\\) or more, got -0.5" --aperture -0.5)
rt_expect_exit(06_depth_of_field.focus_zero 06_depth_of_field 2 "--focus must be more than 0, got 0" --focus 0)
rt_expect_exit(06_depth_of_field.aperture_not_finite 06_depth_of_field 2 "--aperture takes a finite number, got 'inf'"
  --aperture inf)
rt_expect_exit(06_depth_of_field.a_camera_ray_per_lens_sample 06_depth_of_field 0
  "rays_primary=2400\n" --width 30 --height 20 --spp 4
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/06_depth_of_field_4spp.png" --stats)
rt_expect_exit(06_depth_of_field.focused_sphere_sharp 06_depth_of_field 0
  "sphere1_circle_of_confusion_pixels=[1-9][0-9.]*\n.*sphere3_circle_of_confusion_pixels=0\n" --width 320 --height 180
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/06_depth_of_field_circles.png" --stats)
rt_expect_exit(06_depth_of_field.pinhole_all_sharp 06_depth_of_field 0
  "sphere1_circle_of_confusion_pixels=0\n" --width 30 --height 20 --aperture 0
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/06_depth_of_field_pinhole.png" --stats)
rt_expect_exit(05_soft_shadows.unknown_sampling 05_soft_shadows 2
  "--sampling takes random or stratified, got 'halton'" --sampling halton)
rt_expect_exit(05_soft_shadows.stratified_needs_a_square 05_soft_shadows 2
  "--light-samples must be a square \\(1, 4, 9, 16, ...\\) for stratified sampling, got 8" --light-samples 8)
rt_expect_exit(05_soft_shadows.light_samples_zero 05_soft_shadows 2 "--light-samples must be between 1 and 65536, got 0"
  --light-samples 0)
rt_expect_exit(05_soft_shadows.reference_not_a_square 05_soft_shadows 2
  "--reference-samples must be a square \\(1, 4, 9, 16, ...\\), got 1000" --sweep --reference-samples 1000)
rt_expect_exit(05_soft_shadows.random_takes_any_count 05_soft_shadows 0 "rays_shadow=[1-9][0-9]*\n"
  --width 30 --height 20 --light-samples 3 --sampling random
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/05_soft_shadows_random3.png" --stats)
