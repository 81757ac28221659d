# The glint command as a user runs it: exit codes and what it prints.
#   glint_cli_test(NAME LABELS EXIT CODE [STDOUT regex] [STDERR_ONE_LINE regex] [SETUP cmd] COMMAND args...)
set(GLINT_CLI_SAMPLE_DIR "${PROJECT_BINARY_DIR}/test-output/cli")
function(glint_cli_test)
  cmake_parse_arguments(ARG "" "NAME;LABELS;EXIT;STDOUT;STDERR_ONE_LINE" "COMMAND" ${ARGN})
  add_test(NAME "cli: ${ARG_NAME}"
    COMMAND "${CMAKE_COMMAND}" "-DCOMMAND=$<TARGET_FILE:glint>;${ARG_COMMAND}" "-DEXPECT_EXIT=${ARG_EXIT}"
            "-DEXPECT_STDOUT=${ARG_STDOUT}" "-DEXPECT_STDERR_ONE_LINE=${ARG_STDERR_ONE_LINE}"
            -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/check_command.cmake")
  set_tests_properties("cli: ${ARG_NAME}" PROPERTIES LABELS "${ARG_LABELS}" FIXTURES_REQUIRED cli_samples)
endfunction()

# Every verb exits without a LeakSanitizer report (sanitizer builds only; issue 24, item 6).
if(GLINT_SANITIZE)
  add_test(NAME "cli: glint's verbs exit without a leak report"
    COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>"
            "-DSUPPRESSIONS=${CMAKE_CURRENT_SOURCE_DIR}/sanitizers/lsan.supp"
            "-DSAMPLE=${GLINT_CLI_SAMPLE_DIR}/sample" "-DSCENE=${PROJECT_SOURCE_DIR}/harness/scenes/mirror_corridor.toml"
            "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/leaks" -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/leak_check.cmake")
  set_tests_properties("cli: glint's verbs exit without a leak report" PROPERTIES LABELS "gpu"
                       FIXTURES_REQUIRED cli_samples)
endif()

# Blender-style renders of the sample frames (tests/capture/blender_capture.h).
add_executable(glint_make_blender_sample cli/make_blender_sample.cpp capture/blender_capture.cpp)
target_link_libraries(glint_make_blender_sample PRIVATE glint_capture)
target_include_directories(glint_make_blender_sample PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}")
glint_target_defaults(glint_make_blender_sample)

# Fixture: the bundled sample sequence plus malformed files made from it, and Blender renders.
add_test(NAME "cli: make samples"
  COMMAND "${CMAKE_COMMAND}" "-DMAKE_SAMPLE=$<TARGET_FILE:glint_make_sample>"
          "-DMAKE_BLENDER=$<TARGET_FILE:glint_make_blender_sample>" "-DDIR=${GLINT_CLI_SAMPLE_DIR}"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/make_cli_samples.cmake")
set_tests_properties("cli: make samples" PROPERTIES FIXTURES_SETUP cli_samples LABELS "unit")

glint_cli_test(NAME "info describes a sample frame" LABELS unit EXIT 0
  STDOUT "64.48.*color.*depth.*normal.*material.*motion.*reflections"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/sample/frame_0000.exr")
glint_cli_test(NAME "info describes a sample sequence" LABELS unit EXIT 0
  STDOUT "2 frames.*frame_0000.exr.*frame_0001.exr"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/sample")
glint_cli_test(NAME "info on a truncated capture prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "truncated.exr"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/truncated.exr")
glint_cli_test(NAME "info on a file that is not EXR prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "not_exr.exr"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/not_exr.exr")
glint_cli_test(NAME "info on a missing file prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "does_not_exist.exr"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/does_not_exist.exr")
glint_cli_test(NAME "an unknown verb is a usage error" LABELS unit EXIT 2
  COMMAND frobnicate)
# Messages that name the real cause (issue 24, item 5).
glint_cli_test(NAME "simulate of a camera looking straight down with the default up names camera.up" LABELS unit
  EXIT 2
  STDERR_ONE_LINE "^glint: [^ ]*straight_down.toml:5: camera.up: the default \\[0, 1, 0\\] is parallel to the view direction \\[0, -1, 0\\] on frame 0. give camera.up a direction across the view"
  COMMAND simulate "${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/straight_down.toml" --out "${GLINT_CLI_SAMPLE_DIR}/straight_down")
glint_cli_test(NAME "simulate warns in one line when surface pixels get the background depth" LABELS gpu EXIT 0
  STDOUT "wrote"
  STDERR_ONE_LINE "^glint: [^ ]*far_wall.toml: warning: [1-9][0-9]* surface pixels on 1 of 1 frame have device depth within 1e-6 of the background's 1 \\(standard depth, near 0.001, far 10000\\), so they replay as sky.*raise camera.near"
  COMMAND simulate "${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/far_wall.toml" --out "${GLINT_CLI_SAMPLE_DIR}/far_wall")
glint_cli_test(NAME "a manifest number beyond a double names the line, not the JSON library's code" LABELS unit EXIT 2
  STDERR_ONE_LINE "overflow_manifest/manifest.json: malformed JSON: line 8: the number 1e999 is too large for a double \\(beyond 1.8e308\\)$"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/overflow_manifest")
glint_cli_test(NAME "a setting beyond its range names the range" LABELS gpu EXIT 2
  STDERR_ONE_LINE "^glint: --set thickness needs a value in 0..1e\\+06, got '1e9'$"
  COMMAND bench reflections --size 16x16 --runs 1 --scene "${PROJECT_SOURCE_DIR}/harness/scenes/glossy_room.toml"
          --set thickness=1e9)
glint_cli_test(NAME "devices lists at least one Vulkan device with its subgroup size" LABELS gpu EXIT 0
  STDOUT "subgroup size [0-9]+"
  COMMAND --validate devices)

# Every bundled scene simulates under the validation layer into a capture that info reads.
foreach(scene IN ITEMS courtyard_penumbra disocclusion glossy_room gltf_engine mirror_corridor mirror_floor
                       mostly_sky shadow_cut spinning_mirror sun_walker swinging_lamp thin_pillars time_of_day
                       toward_mirror)
  add_test(NAME "cli: the bundled scene ${scene} simulates into a capture that info describes"
    COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DSCENE=${PROJECT_SOURCE_DIR}/harness/scenes/${scene}.toml"
            "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/scenes/${scene}" -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/simulate_scene.cmake")
  set_tests_properties("cli: the bundled scene ${scene} simulates into a capture that info describes"
                       PROPERTIES LABELS gpu)
endforeach()

# glint bench <effect>: the effect alone on its descriptor's bench scene (here named with
# --scene, since the tests do not run from the repository root).
set(GLINT_GLOSSY_ROOM "${PROJECT_SOURCE_DIR}/harness/scenes/glossy_room.toml")
glint_cli_test(NAME "bench times the depth pyramid under validation" LABELS gpu EXIT 0
  STDOUT "effect depth_pyramid on [^ ]*glossy_room.toml: 97x61.*depth_pyramid/build"
  COMMAND --validate bench depth_pyramid --size 97x61 --runs 2 --scene "${GLINT_GLOSSY_ROOM}"
          --depth reversed --set pyramid.closestAndFarthest=true)
glint_cli_test(NAME "bench times a partial depth pyramid without level 0 under validation" LABELS gpu EXIT 0
  STDOUT "set pyramid.levelCount=3.*set pyramid.copyLevel0=false.*depth_pyramid/build"
  COMMAND --validate bench depth_pyramid --size 97x61 --runs 2 --scene "${GLINT_GLOSSY_ROOM}"
          --set pyramid.levelCount=3 --set pyramid.copyLevel0=false)
glint_cli_test(NAME "bench times roughness extraction under validation" LABELS gpu EXIT 0
  STDOUT "roughness/extract_roughness"
  COMMAND --validate bench roughness --size 33x17 --runs 2 --scene "${GLINT_GLOSSY_ROOM}")
glint_cli_test(NAME "bench of an unknown effect is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "unknown effect 'nosuch'"
  COMMAND bench nosuch --runs 1)
glint_cli_test(NAME "bench with a malformed size is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "--size must read WxH"
  COMMAND bench depth_pyramid --size large)
glint_cli_test(NAME "bench of an effect with --effects is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: bench: --effects applies to captures and scene files, not to the effect 'shadows'$"
  COMMAND bench shadows --effects reflections --runs 1)
glint_cli_test(NAME "bench --scene without an effect named is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: bench: --scene applies to an effect named"
  COMMAND bench "${GLINT_GLOSSY_ROOM}" --scene "${GLINT_GLOSSY_ROOM}" --runs 1)
glint_cli_test(NAME "bench times every shadow denoiser pass under validation" LABELS gpu EXIT 0
  STDOUT "shadows/prepare.*shadows/classify.*shadows/filter.*total"
  COMMAND --validate bench shadows --size 41x23 --runs 2
          --scene "${PROJECT_SOURCE_DIR}/harness/scenes/courtyard_penumbra.toml")
glint_cli_test(NAME "bench times SSSR and the denoiser on a simulated scene under validation" LABELS gpu EXIT 0
  STDOUT "classify.*compact_noise_args.*intersect.*reproject.*prefilter.*resolve.*total.*traced_fraction"
  COMMAND --validate bench reflections --size 64x36 --runs 2 --scene "${GLINT_GLOSSY_ROOM}"
          --set denoise=true --set debugOutput=true)
glint_cli_test(NAME "bench of an effect with an unknown setting is a usage error naming it" LABELS gpu EXIT 2
  STDERR_ONE_LINE "unknown setting 'nosuch'"
  COMMAND bench reflections --size 16x16 --runs 1 --scene "${GLINT_GLOSSY_ROOM}" --set nosuch=1)

# glint bench on captures and glint study (docs/accuracy-vs-time.md).
glint_cli_test(NAME "bench on a sample capture prints per-pass medians as JSON under validation" LABELS gpu EXIT 0
  STDOUT "^[{].*passes.*medianUs.*reflections/intersect.*subgroupSize.*[}] *$"
  COMMAND --validate bench "${GLINT_CLI_SAMPLE_DIR}/sample" --runs 2 --json -)
glint_cli_test(NAME "bench simulates a scene file at the requested resolution and times its passes" LABELS gpu EXIT 0
  STDOUT "subgroup [0-9]+.*courtyard_penumbra.toml: 40x24.*shadows/filter2.*total"
  COMMAND --validate bench "${PROJECT_SOURCE_DIR}/harness/scenes/courtyard_penumbra.toml" --resolution 40x24
          --runs 2)
glint_cli_test(NAME "bench on a missing capture prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "does_not_exist.exr: no such file"
  COMMAND bench "${GLINT_CLI_SAMPLE_DIR}/does_not_exist.exr" --runs 1)
glint_cli_test(NAME "bench of a capture at another resolution prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "is 64x48, not the --resolution 32x32"
  COMMAND bench "${GLINT_CLI_SAMPLE_DIR}/sample" --resolution 32x32 --runs 1)

# No effect's name is branched on in harness/replay or harness/cli (its descriptor says instead).
add_test(NAME "cli: the harness compares no effect name (descriptors say how effects are judged)"
  COMMAND "${CMAKE_COMMAND}" "-DSOURCE=${PROJECT_SOURCE_DIR}" -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/effect_names.cmake")
set_tests_properties("cli: the harness compares no effect name (descriptors say how effects are judged)"
  PROPERTIES LABELS unit)

# The lavapipe-sized study as a smoke test; run from the source root, where its scenes are.
set(GLINT_STUDY_DIR "${PROJECT_BINARY_DIR}/test-output/study")
add_test(NAME "cli: study --quick and its scaling runs write finite results under validation"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DOUT=${GLINT_STUDY_DIR}"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/study_quick.cmake")
set_tests_properties("cli: study --quick and its scaling runs write finite results under validation"
  PROPERTIES LABELS gpu WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}" FIXTURES_SETUP study_quick)
add_test(NAME "cli: study.py adds FLIP and Pareto fronts to the quick study and plots it"
  COMMAND "${CMAKE_COMMAND}" "-DPYTHON=${PROJECT_SOURCE_DIR}/build/venv/bin/python"
          "-DSCRIPT=${PROJECT_SOURCE_DIR}/scripts/study.py" "-DOUT=${GLINT_STUDY_DIR}"
          "-DVALUE_TESTS=${CMAKE_CURRENT_SOURCE_DIR}/cli/study_py_test.py"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/study_python.cmake")
set_tests_properties("cli: study.py adds FLIP and Pareto fronts to the quick study and plots it"
  PROPERTIES LABELS gpu FIXTURES_REQUIRED study_quick SKIP_REGULAR_EXPRESSION "SKIP:")

# glint view (docs/viewer.md): its script reader and pictures, then the window under Xvfb.
glint_add_test_suite(NAME view LABELS unit SOURCES cli/view_test.cpp LIBS glint_viewer)
add_executable(glint_compare_png cli/compare_png.cpp)
target_link_libraries(glint_compare_png PRIVATE glint_report)
glint_target_defaults(glint_compare_png)
add_test(NAME "cli: glint view's screenshots equal glint run's images, and scripts change settings and views"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DCOMPARE=$<TARGET_FILE:glint_compare_png>"
          "-DSCENES=${PROJECT_SOURCE_DIR}/harness/scenes" "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/view"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/viewer.cmake")
set_tests_properties("cli: glint view's screenshots equal glint run's images, and scripts change settings and views"
  PROPERTIES LABELS "gpu" SKIP_REGULAR_EXPRESSION "GLINT_SKIP: ")
