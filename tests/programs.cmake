# The chapter programs as a user meets them: bad input gets one line naming the problem and exit
# status 2; a small render exits 0 and prints its stats.
function(rt_expect_exit name program status match)
  string(JOIN "|" args ${ARGN})
  add_test(NAME programs.${name}
    COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:${program}>" -D "ARGS=${args}" -D "STATUS=${status}"
      -D "MATCH=${match}" -P "${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake")
  set_tests_properties(programs.${name} PROPERTIES LABELS "programs")
endfunction()

# Every program returns write_figure's status: a NaN pixel exits 3 with its message.
foreach(chapter IN LISTS RT_CHAPTERS)
  add_test(NAME programs.${chapter}.nan_pixel_fails
    COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:${chapter}>" -D POISON=1 -D STATUS=3
      -D "MATCH=a NaN or infinite radiance reached 1 pixels"
      -D "ARGS=--width|8|--height|6|--out|${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}_poisoned.png"
      -P "${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake")
  set_tests_properties(programs.${chapter}.nan_pixel_fails PROPERTIES LABELS "programs")
endforeach()

# A figure drawn by unfinished exercises says which stubs drew it (a handout's first render); the
# solutions' figure says nothing of stubs.
if(RT_EXERCISES_DIR STREQUAL "${PROJECT_SOURCE_DIR}/exercises")
  foreach(chapter 01_ray_casting 03_reflection_refraction)
    string(SUBSTRING "${chapter}" 0 2 nn)
    rt_chapter_libraries(libs ${nn} stubs)
    add_executable(stubs_${chapter} "${PROJECT_SOURCE_DIR}/chapters/${chapter}/main.cpp")
    target_link_libraries(stubs_${chapter} PRIVATE ${libs} nff_generators)
  endforeach()
  rt_expect_exit(01_ray_casting.stubs_named stubs_01_ray_casting 0
    "was drawn with 2 exercises still stubs: 01.1 01.3 \\(grep -n \"EXERCISE 01.1\""
    --width 8 --height 6 --out "${CMAKE_CURRENT_BINARY_DIR}/programs/01_stubs.png")
  rt_expect_exit(03_reflection_refraction.stubs_named stubs_03_reflection_refraction 0
    "exercises still stubs: 01.1 .*03.5 "
    --width 8 --height 6 --out "${CMAKE_CURRENT_BINARY_DIR}/programs/03_stubs.png")
endif()
add_test(NAME programs.01_ray_casting.solutions_name_no_stub
  COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:01_ray_casting>" -D STATUS=0 -D MATCH=. -D "NO_MATCH=stub"
    -D "ARGS=--width|8|--height|6|--out|${CMAKE_CURRENT_BINARY_DIR}/programs/01_solutions.png|--stats"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake")
set_tests_properties(programs.01_ray_casting.solutions_name_no_stub PROPERTIES LABELS "programs")

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
rt_expect_exit(04_shadow_feelers.scale_zero 04_shadow_feelers 2 "--scale must lie strictly between 1e-07 and" --scale 0)
rt_expect_exit(04_shadow_feelers.scale_tiny 04_shadow_feelers 2 "--scale must lie strictly between 1e-07 and 1e\\+07, got 1e-30"
  --scale 1e-30)
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

# Scene files (--scene FILE.nff, issue: scenes from files): every program from chapter 02 on renders
# each of the kit's scenes; a bad file or a bad combination of options is one line and exit 2.
set(kit_scenes spheres cones concave patches)
# How many objects each holds (spheres, triangles after triangulation, cones): chapter 02 tests
# each of them once per eye ray, so its count of intersection tests proves the whole file arrived.
set(objects_spheres 5)
set(objects_cones 8)
set(objects_concave 29)
set(objects_patches 70)
set(scene_chapters 02_spheres_triangles 03_reflection_refraction 04_shadow_feelers 05_soft_shadows 06_depth_of_field
  07_uniform_grid 08_mailboxing 09_hashed_voxels 10_hierarchies)
foreach(chapter IN LISTS scene_chapters)
  foreach(scene IN LISTS kit_scenes)
    # 24 wide: the file's 400 x 400 keeps its aspect, so 24 x 24 = 576 eye rays.
    set(expected "rays_primary=576\n")
    if(chapter MATCHES "^02_")
      math(EXPR tests "576 * ${objects_${scene}}")
      string(APPEND expected ".*intersection_tests=${tests}\n")
    endif()
    rt_expect_exit(${chapter}.scene_${scene} ${chapter} 0 "${expected}"
      --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 24 --stats
      --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}_${scene}.png")
  endforeach()
  rt_expect_exit(${chapter}.scene_missing ${chapter} 2 "/no/such/scene.nff:1: no such file" --scene /no/such/scene.nff)
  rt_expect_exit(${chapter}.scene_malformed ${chapter} 2 "sphere_negative_radius.nff:13: [^\n]*radius"
    --scene "${CMAKE_CURRENT_SOURCE_DIR}/bad_scenes/sphere_negative_radius.nff")
  rt_expect_exit(${chapter}.scene_with_sweep ${chapter} 2 "--sweep measures the chapter's own scenes; it does not take --scene"
    --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --sweep)
endforeach()
# A standard file with a patch of no area renders, with one warning naming its line, and counts it.
foreach(chapter IN LISTS scene_chapters)
  rt_expect_exit(${chapter}.scene_zero_area_patch ${chapter} 0
    "skipped_polygons=1\n.*warning: [^\n]*zero_area_patch.nff:18: patch: has fewer than 3 distinct vertices [(]its corners coincide[)]: skipped"
    --scene "${CMAKE_CURRENT_SOURCE_DIR}/scene_files/zero_area_patch.nff" --stats
    --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}_zero_area_patch.png")
endforeach()
# A chapter that shades mirrors and glass opaque says so (spheres.nff has both).
foreach(chapter 04_shadow_feelers 05_soft_shadows 06_depth_of_field 07_uniform_grid 08_mailboxing 09_hashed_voxels 10_hierarchies)
  rt_expect_exit(${chapter}.scene_says_what_it_does_not_model ${chapter} 0
    "${chapter}: note: [^\n]*spheres.nff: [1-9][0-9]* mirror \\(Ks > 0\\) and [1-9][0-9]* glass \\(T > 0\\) materials are shaded opaque"
    --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --width 16
    --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}_opaque_note.png")
endforeach()
rt_expect_exit(02_spheres_triangles.scene_file_resolution 02_spheres_triangles 0 "rays_primary=160000\n"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --stats
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/02_spheres_triangles_file_resolution.png")
rt_expect_exit(03_reflection_refraction.scene_glass_refracts 03_reflection_refraction 0 "rays_refracted=[1-9]"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --width 40 --stats
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/03_reflection_refraction_scene_glass.png")
rt_expect_exit(04_shadow_feelers.scene_scale 04_shadow_feelers 2 "--scale scales the figure's scene; it does not apply to --scene"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --scale 2)
rt_expect_exit(04_shadow_feelers.classic_without_scene 04_shadow_feelers 2 "--classic .* needs --scene FILE.nff" --classic)
rt_expect_exit(04_shadow_feelers.classic_offset 04_shadow_feelers 2 "--offset and --feelers do not apply"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --classic --offset none)
rt_expect_exit(04_shadow_feelers.classic_spp 04_shadow_feelers 2 "--classic shoots one eye ray through each pixel corner: --spp must be 1, got 4"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --classic --spp 4)
set(many_lights "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.1\nresolution 8 8\nf 1 1 1 1 0 0 0 0\ns 0 0 0 1\n")
foreach(k RANGE 1 300)
  string(APPEND many_lights "l ${k} 10 10\n")
endforeach()
file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/programs/many_lights.nff" "${many_lights}")
rt_expect_exit(05_soft_shadows.too_many_lights 05_soft_shadows 2
  "many_lights.nff: 300 lights; chapter 05 samples every light at every hit and takes at most 256"
  --scene "${CMAKE_CURRENT_BINARY_DIR}/programs/many_lights.nff")
rt_expect_exit(04_shadow_feelers.image_too_large 04_shadow_feelers 2
  "an image of 16384 x 16384 pixels needs about 3221 MB of colour; the limit is 33554432 pixels" --width 16384 --height 16384)
rt_expect_exit(04_shadow_feelers.scene_image_too_large 04_shadow_feelers 2 "an image of 16384 x 8192 pixels"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --width 16384 --height 8192)
rt_expect_exit(04_shadow_feelers.unwritable_out_before_render 04_shadow_feelers 2
  "/proc/no/such/folder/x.png: cannot write the PNG file" --width 4000 --height 4000 --spp 64 --out /proc/no/such/folder/x.png)
rt_expect_exit(04_shadow_feelers.unwritable_csv_before_sweep 04_shadow_feelers 2
  "/proc/no/such/folder/x.csv: cannot write the CSV file" --sweep --csv /proc/no/such/folder/x.csv)
rt_expect_exit(07_uniform_grid.unwritable_heatmap_before_render 07_uniform_grid 2
  "/proc/no/such/folder/h.png: cannot write the PNG file" --heatmap /proc/no/such/folder/h.png)
rt_expect_exit(05_soft_shadows.light_size_without_scene 05_soft_shadows 2 "--light-size sizes a scene file's lights" --light-size 0.2)

# The classic NFF test rules, their counts worked by hand in each scene file's comments.
set(classic_counts_one_wall "eye_rays=9\neye_hits=9\nreflect_rays=0\nrefract_rays=0\nshadow_rays=9\nshadow_blocked=0\nsecondary_hits=0\n")
set(classic_counts_two_mirrors "eye_rays=9\neye_hits=9\nreflect_rays=36\nrefract_rays=0\nshadow_rays=45\nshadow_blocked=0\nsecondary_hits=36\n")
set(classic_counts_back_face "eye_rays=9\neye_hits=9\nreflect_rays=0\nrefract_rays=0\nshadow_rays=9\nshadow_blocked=9\nsecondary_hits=0\n")
set(classic_counts_total_internal_reflection "eye_rays=9\neye_hits=9\nreflect_rays=9\nrefract_rays=0\nshadow_rays=9\nshadow_blocked=0\nsecondary_hits=0\n")
set(classic_counts_hither_past_wall "eye_rays=9\neye_hits=0\nreflect_rays=0\nrefract_rays=0\nshadow_rays=0\nshadow_blocked=0\nsecondary_hits=0\n")
set(classic_counts_refraction_pane "eye_rays=9\neye_hits=9\nreflect_rays=9\nrefract_rays=9\nshadow_rays=18\nshadow_blocked=9\nsecondary_hits=9\n")
set(classic_counts_light_behind "eye_rays=9\neye_hits=9\nreflect_rays=0\nrefract_rays=0\nshadow_rays=0\nshadow_blocked=0\nsecondary_hits=0\n")
foreach(scene one_wall two_mirrors back_face total_internal_reflection hither_past_wall refraction_pane light_behind)
  foreach(chapter 04_shadow_feelers 07_uniform_grid 08_mailboxing 09_hashed_voxels 10_hierarchies)
    rt_expect_exit(${chapter}.classic_${scene} ${chapter} 0 "^${classic_counts_${scene}}"
      --scene "${CMAKE_CURRENT_SOURCE_DIR}/classic/${scene}.nff" --classic --stats
      --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}_classic_${scene}.png")
  endforeach()
endforeach()
# --two-sided (SPD's teapot rule): the near wall's back is seen, lit by the light on the eye's side.
foreach(chapter 04_shadow_feelers 07_uniform_grid 08_mailboxing 09_hashed_voxels 10_hierarchies)
  rt_expect_exit(${chapter}.classic_back_face_two_sided ${chapter} 0
    "^eye_rays=9\neye_hits=9\nreflect_rays=0\nrefract_rays=0\nshadow_rays=9\nshadow_blocked=0\nsecondary_hits=0\n"
    --scene "${CMAKE_CURRENT_SOURCE_DIR}/classic/back_face.nff" --classic --two-sided --stats
    --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${chapter}_classic_two_sided.png")
  rt_expect_exit(${chapter}.two_sided_without_classic ${chapter} 2 "--two-sided is a rule of --classic" --two-sided)
endforeach()
# A w x h image shoots (w + 1) x (h + 1) eye rays.
rt_expect_exit(04_shadow_feelers.classic_corner_rays 04_shadow_feelers 0 "^eye_rays=651\n"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/cones.nff" --classic --width 30 --height 20 --stats
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/04_shadow_feelers_classic_corners.png")

# From chapter 07 on: an accelerator renders brute force's picture, byte for byte, with brute force's
# rays, in the chapter modes and by the classic rules, on the kit's scenes and generated ones.
# rt_same_render(<name> <program> FIRST <options> SECOND <options> ARGS <options> [GENERATE <nff_generate args>]
#                [EXPECT <regex the second run's --stats match>] [SECOND_PROGRAM <program of the second run>])
function(rt_same_render name program)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "EXPECT;SECOND_PROGRAM" "FIRST;SECOND;ARGS;GENERATE")
  string(JOIN "|" first ${arg_FIRST})
  string(JOIN "|" second ${arg_SECOND})
  string(JOIN "|" args ${arg_ARGS})
  set(generator "")
  if(arg_GENERATE)
    string(JOIN "|" generate ${arg_GENERATE})
    set(generator -D "GENERATOR=$<TARGET_FILE:nff_generate>" -D "GENERATE=${generate}")
  endif()
  if(arg_SECOND_PROGRAM)
    list(APPEND generator -D "SECOND_PROGRAM=$<TARGET_FILE:${arg_SECOND_PROGRAM}>")
  endif()
  add_test(NAME programs.${name}
    COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:${program}>" -D "ARGS=${args}" -D "FIRST=${first}"
      -D "SECOND=${second}" -D "OUT=${CMAKE_CURRENT_BINARY_DIR}/programs/${name}" ${generator} -D "EXPECT=${arg_EXPECT}"
      -P "${CMAKE_CURRENT_SOURCE_DIR}/same_render.cmake")
  set_tests_properties(programs.${name} PROPERTIES LABELS "programs")
endfunction()

# An open exercise's option in its chapter's program (07.7's --resolution open, 08.4's --mailbox
# cache), with the reference's answer in the student's place: four tests, each named by the caller.
#   SAME <name> FIRST <options> ARGS <options> GENERATE <args>: the option renders what FIRST does;
#   STATS <name> <regex>: --stats of the figure with the option matches;
#   UNKNOWN <name> <values> <bad>: another value is refused, the message naming the option's values;
#   ELSEWHERE <name> <shapes> <accel>: with an --accel the option does not shape, refused, naming those it does.
function(rt_open_option_tests program option value)
  cmake_parse_arguments(PARSE_ARGV 3 arg "" "" "SAME;FIRST;ARGS;GENERATE;STATS;UNKNOWN;ELSEWHERE")
  list(GET arg_SAME 0 same)
  rt_same_render(${program}.${same} ${program} FIRST ${arg_FIRST} SECOND ${option} ${value} ARGS ${arg_ARGS}
    GENERATE ${arg_GENERATE})
  list(GET arg_STATS 0 stats)
  list(GET arg_STATS 1 stats_match)
  rt_expect_exit(${program}.${stats} ${program} 0 "${stats_match}" ${option} ${value} --width 30 --height 20 --stats
    --out "${CMAKE_CURRENT_BINARY_DIR}/programs/${program}_${stats}.png")
  list(GET arg_UNKNOWN 0 unknown)
  list(GET arg_UNKNOWN 1 values)
  list(GET arg_UNKNOWN 2 bad)
  rt_expect_exit(${program}.${unknown} ${program} 2 "${option} takes ${values}, got '${bad}'" ${option} ${bad})
  list(GET arg_ELSEWHERE 0 elsewhere)
  list(GET arg_ELSEWHERE 1 shapes)
  list(GET arg_ELSEWHERE 2 accel)
  rt_expect_exit(${program}.${elsewhere} ${program} 2 "${option} shapes ${shapes}; it does not apply to --accel ${accel}"
    --accel ${accel} ${option} ${value})
endfunction()

# One brute force: chapter 04's program and chapters 07-10's with --accel brute render the same picture
# with the same rays. Each program compiles the shared inline code on its own, so only the programs can
# show that they agree: the tree's cones once differed by GCC's rounding (cone.hpp, cone_surface).
foreach(chapter 07_uniform_grid 08_mailboxing 09_hashed_voxels 10_hierarchies)
  foreach(mode plain classic)
    set(extra "")
    if(mode STREQUAL "classic")
      set(extra --classic)
    endif()
    rt_same_render(${chapter}.brute_as_chapter_04_${mode}_tree 04_shadow_feelers SECOND_PROGRAM ${chapter}
      FIRST --threads 1 SECOND --accel brute --threads 1 ARGS --width 128 --height 128 ${extra}
      GENERATE tree --depth 3)
  endforeach()
endforeach()
foreach(scene IN LISTS kit_scenes)
  foreach(mode plain classic)
    set(extra "")
    if(mode STREQUAL "classic")
      set(extra --classic)
    endif()
    rt_same_render(07_uniform_grid.grid_as_brute_${mode}_${scene} 07_uniform_grid FIRST --accel brute SECOND --accel grid
      ARGS --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 48 ${extra})
  endforeach()
endforeach()
foreach(generated "sphereflake;2" "pyramid;3" "tree;3" "mountain;4")
  list(GET generated 0 kind)
  list(GET generated 1 depth)
  rt_same_render(07_uniform_grid.grid_as_brute_classic_${kind}${depth} 07_uniform_grid FIRST --accel brute
    SECOND --accel grid --lambda 4 ARGS --width 64 --classic GENERATE ${kind} --depth ${depth})
endforeach()
# Two threads, with or without OpenMP (the kit's loop is std::thread): two drew the picture, the same one.
rt_same_render(07_uniform_grid.figure_threads 07_uniform_grid FIRST --threads 1 SECOND --threads 2 ARGS --width 80 --height 45
  EXPECT "\nthreads=2\n")
rt_same_render(01_ray_casting.figure_threads 01_ray_casting FIRST --threads 1 SECOND --threads 2 ARGS --width 80 --height 45
  EXPECT "\nthreads=2\n")
rt_expect_exit(07_uniform_grid.figure_stats 07_uniform_grid 0
  "rays_primary=600\n.*accel=grid\nobjects=32772\ncells_visited=[1-9][0-9]*\ngrid_resolution=[0-9]+x[0-9]+x[0-9]+\n.*references_per_object=[1-9]"
  --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/07_uniform_grid_stats.png")
# Your grid's shape (07.7, here the reference's) renders the figure too, and a teapot in a stadium
# as brute force does: the build lists the objects in the cells it asks for (grid_lambda 0: no
# lambda asked).
rt_open_option_tests(07_uniform_grid --resolution open
  SAME open_resolution_as_brute_stadium FIRST --accel brute ARGS --width 64 GENERATE stadium --depth 2
  STATS open_resolution_stats "accel=grid\nobjects=32772\ncells_visited=[1-9][0-9]*\ngrid_resolution=[0-9]+x[0-9]+x[0-9]+\ngrid_lambda=0\n"
  UNKNOWN unknown_resolution "rule or open" cubic
  ELSEWHERE resolution_with_brute grid brute)
rt_expect_exit(07_uniform_grid.heatmap_written 07_uniform_grid 0 "accel=brute"
  --scene "${PROJECT_SOURCE_DIR}/common/scenes/spheres.nff" --width 32 --accel brute --heat-of tests --stats
  --heatmap "${CMAKE_CURRENT_BINARY_DIR}/programs/07_uniform_grid_heat.png"
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/07_uniform_grid_heat_scene.png")
# --accel's names and the options' checks come from the registry (programs/structures.hpp): each
# program lists the structures of its chapter and the earlier ones, and no later one.
rt_expect_exit(07_uniform_grid.unknown_accel 07_uniform_grid 2 "--accel takes brute or grid, got 'kd-tree'" --accel kd-tree)
rt_expect_exit(07_uniform_grid.lambda_with_brute 07_uniform_grid 2 "--lambda shapes grid; it does not apply to --accel brute"
  --accel brute --lambda 3)
rt_expect_exit(07_uniform_grid.lambda_zero 07_uniform_grid 2 "--lambda must lie strictly between 0 and" --lambda 0)
rt_expect_exit(07_uniform_grid.lambda_too_dense 07_uniform_grid 2 "cells .* passes the limit of 33554432 cells: choose a smaller lambda"
  --lambda 5000 --width 8 --height 8)
rt_expect_exit(07_uniform_grid.unknown_heat 07_uniform_grid 2 "--heat-of takes tests or cells, got 'time'" --heat-of time)
rt_expect_exit(07_uniform_grid.classic_without_scene 07_uniform_grid 2 "--classic .* needs --scene FILE.nff" --classic)

# Chapter 08: the grid with mailboxes renders brute force's picture and rays, and the grid's without
# them, at 1 and 2 threads; on the kit's scenes and on long thin sticks (many cells per object).
foreach(scene IN LISTS kit_scenes)
  rt_same_render(08_mailboxing.mailboxes_as_brute_classic_${scene} 08_mailboxing FIRST --accel brute SECOND --accel grid-mailbox
    ARGS --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 48 --classic)
endforeach()
foreach(mode plain classic)
  set(extra "")
  if(mode STREQUAL "classic")
    set(extra --classic)
  endif()
  rt_same_render(08_mailboxing.mailboxes_on_off_${mode}_sticks 08_mailboxing FIRST --accel grid SECOND --accel grid-mailbox
    ARGS --width 64 --lambda 8 ${extra} GENERATE sticks --depth 2)
  rt_same_render(08_mailboxing.mailboxes_threads_${mode}_sticks 08_mailboxing FIRST --threads 1 SECOND --threads 2
    ARGS --width 64 --lambda 8 ${extra} GENERATE sticks --depth 2)
endforeach()
rt_same_render(08_mailboxing.mailboxes_as_brute_tree 08_mailboxing FIRST --accel brute SECOND --accel grid-mailbox
  ARGS --width 48 GENERATE tree --depth 3)
rt_expect_exit(08_mailboxing.figure_stats 08_mailboxing 0
  "rays_primary=600\n.*accel=grid-mailbox\nobjects=8002\n.*tests_answered_by_mailboxes=[1-9][0-9]*\n.*mailbox_bytes_per_thread=128032\n"
  --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/08_mailboxing_stats.png")
# Your ray cache (08.4, here the reference's) renders the figure too: the same picture as the
# mailboxes, 1 KB a thread.
rt_open_option_tests(08_mailboxing --mailbox cache
  SAME cache_as_mailboxes_sticks FIRST --accel grid-mailbox ARGS --width 64 --lambda 8 GENERATE sticks --depth 2
  STATS cache_stats "accel=grid-mailbox\nobjects=8002\n.*tests_answered_by_mailboxes=[1-9][0-9]*\n.*mailbox_bytes_per_thread=1024\n"
  UNKNOWN unknown_mailbox "object or cache" ray
  ELSEWHERE mailbox_with_grid grid-mailbox grid)
rt_expect_exit(08_mailboxing.no_answers_without_mailboxes 08_mailboxing 0 "tests_answered_by_mailboxes=0\n"
  --width 30 --height 20 --stats --accel grid --out "${CMAKE_CURRENT_BINARY_DIR}/programs/08_mailboxing_off.png")
rt_expect_exit(08_mailboxing.unknown_accel 08_mailboxing 2 "--accel takes brute, grid or grid-mailbox, got 'yes'" --accel yes)
rt_expect_exit(08_mailboxing.lambda_with_brute 08_mailboxing 2 "--lambda shapes grid or grid-mailbox; it does not apply to --accel brute"
  --accel brute --lambda 3)
rt_expect_exit(08_mailboxing.unknown_heat 08_mailboxing 2 "--heat-of takes saved, tests or cells, got 'time'" --heat-of time)

# Chapter 09: the hashed grid renders brute force's picture and rays, at 1 and 2 threads, with a
# table of any size, on the kit's scenes and the teapot in a stadium.
foreach(scene IN LISTS kit_scenes)
  rt_same_render(09_hashed_voxels.hashed_as_brute_classic_${scene} 09_hashed_voxels FIRST --accel brute SECOND --accel hashed
    ARGS --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 48 --classic)
endforeach()
rt_same_render(09_hashed_voxels.hashed_as_dense_stadium 09_hashed_voxels FIRST --accel grid SECOND --accel hashed
  ARGS --width 64 GENERATE stadium --depth 2)
rt_same_render(09_hashed_voxels.tiny_table_stadium 09_hashed_voxels FIRST --table-size 3 SECOND --table-size 1000003
  ARGS --width 64 --classic GENERATE stadium --depth 2)
rt_same_render(09_hashed_voxels.hashed_threads_stadium 09_hashed_voxels FIRST --threads 1 SECOND --threads 2
  ARGS --width 64 GENERATE stadium --depth 2)
# Your hash (09.6, --table-hash open) files the same cells in other buckets: the same picture, and
# its lookups compare keys the program counts.
rt_same_render(09_hashed_voxels.open_hash_as_mod_lattice 09_hashed_voxels FIRST --table-hash mod SECOND --table-hash open
  ARGS --width 64 --classic GENERATE lattice --depth 6)
rt_expect_exit(09_hashed_voxels.open_hash_stats 09_hashed_voxels 0
  "table_probes=[1-9][0-9]*\ntable_lookups=[1-9][0-9]*\n.*table_hash=open\n"
  --table-hash open --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/09_hashed_voxels_open_stats.png")
rt_expect_exit(09_hashed_voxels.unknown_table_hash 09_hashed_voxels 2 "--table-hash takes mod or open, got 'prime'"
  --table-hash prime)
rt_expect_exit(09_hashed_voxels.table_size_with_open_hash 09_hashed_voxels 2
  "--table-size is the size of p mod M; with --table-hash open your 09.6 chooses it" --table-hash open --table-size 17)
rt_expect_exit(09_hashed_voxels.figure_stats 09_hashed_voxels 0
  "rays_primary=600\n.*accel=hashed\nobjects=21250\n.*table_lookups_skipped=[1-9][0-9]*\ngrid_resolution=361x42x361\n.*table_load=0\\.[0-9]+\n"
  --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/09_hashed_voxels_stats.png")
rt_expect_exit(09_hashed_voxels.unknown_accel 09_hashed_voxels 2 "--accel takes brute, grid, grid-mailbox or hashed, got 'octree'" --accel octree)
rt_expect_exit(09_hashed_voxels.table_size_with_grid 09_hashed_voxels 2
  "--table-size shapes hashed; it does not apply to --accel grid" --accel grid --table-size 17)
rt_expect_exit(09_hashed_voxels.too_fine 09_hashed_voxels 2
  "a hashed grid of 4096 x 634 x 4096 cells passes the limit of 2\\^31 cell addresses: choose a smaller lambda"
  --lambda 900000 --width 8 --height 8)

# Chapter 10: the BVH and its 4-wide form render brute force's picture and rays, SAH and median, at 1
# and 2 threads.
foreach(scene IN LISTS kit_scenes)
  rt_same_render(10_hierarchies.bvh_as_brute_classic_${scene} 10_hierarchies FIRST --accel brute SECOND --accel bvh
    ARGS --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 48 --classic)
endforeach()
foreach(scene IN LISTS kit_scenes)
  rt_same_render(10_hierarchies.bvh4_as_brute_classic_${scene} 10_hierarchies FIRST --accel brute SECOND --accel bvh4
    ARGS --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 48 --classic)
endforeach()
rt_same_render(10_hierarchies.bvh4_as_bvh_stadium 10_hierarchies FIRST --accel bvh SECOND --accel bvh4
  ARGS --width 96 --height 54)
foreach(scene IN LISTS kit_scenes)
  rt_same_render(10_hierarchies.hgrid_as_brute_classic_${scene} 10_hierarchies FIRST --accel brute
    SECOND --accel hgrid --leaf-size 2 --max-depth 3
    ARGS --scene "${PROJECT_SOURCE_DIR}/common/scenes/${scene}.nff" --width 48 --classic)
endforeach()
rt_same_render(10_hierarchies.hgrid_as_bvh_stadium 10_hierarchies FIRST --accel bvh SECOND --accel hgrid
  ARGS --width 64 --classic GENERATE stadium --depth 2)
rt_same_render(10_hierarchies.sah_as_median_stadium 10_hierarchies FIRST --split median SECOND --split sah
  ARGS --width 64 GENERATE stadium --depth 2)
rt_same_render(10_hierarchies.bvh_as_hashed_stadium 10_hierarchies FIRST --accel hashed SECOND --accel bvh
  ARGS --width 64 --classic GENERATE stadium --depth 2)
rt_same_render(10_hierarchies.leaf_sizes_sticks 10_hierarchies FIRST --leaf-size 1 SECOND --leaf-size 16
  ARGS --width 64 GENERATE sticks --depth 2)
rt_same_render(10_hierarchies.bvh_threads_tree 10_hierarchies FIRST --threads 1 SECOND --threads 2
  ARGS --width 64 --classic GENERATE tree --depth 4)
rt_expect_exit(10_hierarchies.figure_stats 10_hierarchies 0
  "rays_primary=600\n.*accel=bvh\nobjects=21250\nnodes_visited=[1-9][0-9]*\n.*bvh_nodes=[1-9][0-9]*\n.*bvh_depth=[1-9][0-9]*\n"
  --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/10_hierarchies_stats.png")
rt_expect_exit(10_hierarchies.bvh4_stats 10_hierarchies 0
  "accel=bvh4\nobjects=21250\nnodes_visited=[1-9][0-9]*\n.*wide_nodes=[1-9][0-9]*\n"
  --accel bvh4 --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/10_hierarchies_bvh4_stats.png")
rt_expect_exit(10_hierarchies.unknown_accel 10_hierarchies 2 "--accel takes brute, grid, grid-mailbox, hashed, .*bvh4.*, got 'kd'" --accel kd)
# Your own build (10.7, here the reference's) renders the figure too, its tree reported as the BVH's.
rt_expect_exit(10_hierarchies.open_split_stats 10_hierarchies 0
  "accel=bvh\nobjects=21250\nnodes_visited=[1-9][0-9]*\n.*bvh_nodes=[1-9][0-9]*\n.*bvh_depth=[1-9][0-9]*\n"
  --split open --width 30 --height 20 --stats --out "${CMAKE_CURRENT_BINARY_DIR}/programs/10_hierarchies_open_stats.png")
rt_expect_exit(10_hierarchies.unknown_split 10_hierarchies 2 "--split takes sah, median or open, got 'random'" --split random)
rt_expect_exit(10_hierarchies.leaf_size_with_grid 10_hierarchies 2
  "--leaf-size shapes hgrid, bvh.*; it does not apply to --accel grid" --accel grid --leaf-size 8)
rt_expect_exit(10_hierarchies.split_with_hgrid 10_hierarchies 2 "--split shapes bvh.*; it does not apply to --accel hgrid"
  --accel hgrid --split median)
rt_expect_exit(10_hierarchies.hgrid_too_deep 10_hierarchies 2
  "--max-depth for the hierarchy of grids must be between 0 and 8, got 9" --accel hgrid --max-depth 9)
rt_expect_exit(10_hierarchies.hgrid_stats 10_hierarchies 0
  "accel=hgrid\nobjects=[0-9]+\n.*cells_visited=[1-9][0-9]*\nhgrid_grids=[1-9][0-9]*\nhgrid_depth=[1-9]\n"
  --accel hgrid --leaf-size 2 --width 48 --height 27 --stats --scene "${PROJECT_SOURCE_DIR}/common/scenes/patches.nff"
  --out "${CMAKE_CURRENT_BINARY_DIR}/programs/10_hierarchies_hgrid_stats.png")
rt_expect_exit(10_hierarchies.depth_too_deep 10_hierarchies 2 "--max-depth must be between 0 and 62, got 63" --max-depth 63)

# The benchmark: on one tiny scene it checks every structure (and Embree, when this build found
# it) against the reference and writes its tables; no timing is asserted. Cones go to Embree as
# user geometry: the kit's cones scene checks that path.
rt_expect_exit(benchmark.tiny benchmark 0 "wrote .*results.csv, any_hit.csv and results.md"
  --tiny --out-dir "${CMAKE_CURRENT_BINARY_DIR}/programs/bench_tiny")
rt_expect_exit(benchmark.tiny_cones benchmark 0 "\\*\\*cones.nff\\*\\* \\(8 objects\\)"
  --tiny --scene "${PROJECT_SOURCE_DIR}/common/scenes/cones.nff" --out-dir "${CMAKE_CURRENT_BINARY_DIR}/programs/bench_cones")
rt_expect_exit(benchmark.missing_scene benchmark 2 "missing.nff" --scene "${PROJECT_SOURCE_DIR}/missing.nff" --tiny
  --out-dir "${CMAKE_CURRENT_BINARY_DIR}/programs/bench_missing")
rt_expect_exit(benchmark.zero_repeat benchmark 2 "--repeat must be between 1 and 100" --repeat 0)

# Long work says how far it is, in a log too: a line per period with the time so far and an
# estimate of what is left, then how long it took (the period forced to 0 for the test).
add_test(NAME programs.progress_in_a_log
  COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:04_shadow_feelers>" -D PROGRESS_SECONDS=0 -D STATUS=0
    -D "MATCH=rendering: +[0-9]+% \\([0-9]+ s, about [0-9]+ s left\\)\n.*rendering: done in [0-9]+ s"
    -D "ARGS=--width|16|--height|8|--threads|1|--out|${CMAKE_CURRENT_BINARY_DIR}/programs/progress.png"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake")
set_tests_properties(programs.progress_in_a_log PROPERTIES LABELS "programs")
# Under Ninja, a figure's render shows its progress as it draws (chapters/chapters.cmake).
if(CMAKE_GENERATOR STREQUAL "Ninja")
  add_test(NAME programs.figures_render_on_the_terminal
    COMMAND ${CMAKE_COMMAND} -D "NINJA_FILE=${CMAKE_BINARY_DIR}/build.ninja"
      -P "${CMAKE_CURRENT_SOURCE_DIR}/figures_on_the_terminal.cmake")
  set_tests_properties(programs.figures_render_on_the_terminal PROPERTIES LABELS "programs")
endif()
# A sweep says it is alive between its measurements, one of which may take half a minute: lines
# from its own thread, the count so far and the time, every period (half a second here, on a
# sweep of chapter 07 shrunk to about 4 s), then the count and the time it took.
add_test(NAME programs.sweep_says_it_is_alive
  COMMAND ${CMAKE_COMMAND} -D "PROGRAM=$<TARGET_FILE:07_uniform_grid>" -D PROGRESS_SECONDS=0.5 -D STATUS=0
    -D "MATCH=\n[0-9]+ structures measured so far \\([0-9]+ s\\)\n(.*\n)?[0-9]+ structures measured in [0-9]+ s"
    -D "ARGS=--sweep|--repeat|1|--width|16|--height|9|--csv|${CMAKE_CURRENT_BINARY_DIR}/programs/sweep_alive.csv"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/expect_exit.cmake")
set_tests_properties(programs.sweep_says_it_is_alive PROPERTIES LABELS "programs")
rt_expect_exit(benchmark.unknown_structure benchmark 2 "--structures: unknown structure 'kd'" --structures bvh,kd --tiny)
