# Foreign captures as a first-time user meets them (issue 26): Blender-style renders of the
# sample frames (glint_make_blender_sample) through the shipped harness/maps/blender.toml.
set(GLINT_BLENDER_MAP "${PROJECT_SOURCE_DIR}/harness/maps/blender.toml")
glint_cli_test(NAME "info --map describes the frames of a Blender render as glint reads them" LABELS unit EXIT 0
  STDOUT "mapped capture .*blender through .*blender.toml: 2 frames, 64x48.*0001.exr:.*color.*depth.*normal.*roughness.*motion.*0002.exr:"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/blender" --map "${GLINT_BLENDER_MAP}")
glint_cli_test(NAME "info on a folder without manifest.json says to pass --map" LABELS unit EXIT 2
  STDERR_ONE_LINE "blender: no manifest.json; for a folder of foreign EXR renders pass --map FILE [(]harness/maps/blender.toml for Blender[)]$"
  COMMAND info "${GLINT_CLI_SAMPLE_DIR}/blender")
glint_cli_test(NAME "run on a folder without manifest.json says to pass --map" LABELS unit EXIT 2
  STDERR_ONE_LINE "blender: no manifest.json; for a folder of foreign EXR renders pass --map FILE"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/blender" --out "${PROJECT_BINARY_DIR}/test-output/cli/foreign_bad")
glint_cli_test(NAME "composite on a render without the Diffuse Color pass names the file, the layer and the pass" LABELS unit EXIT 2
  STDERR_ONE_LINE "blender/0001.exr: effect 'reflections' needs the capture layer 'material' [(]for composite[)].*ViewLayer.DiffCol.R.*blender.toml.*Diffuse Color.*leave composite off$"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/blender" --map "${GLINT_BLENDER_MAP}" --set composite=true
          --out "${PROJECT_BINARY_DIR}/test-output/cli/foreign_bad")
add_test(NAME "cli: a Blender render replays with and without composite; outputs carry its frame numbers"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DSAMPLES=${GLINT_CLI_SAMPLE_DIR}"
          "-DMAP=${GLINT_BLENDER_MAP}" "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/foreign_run"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/foreign_run.cmake")
set_tests_properties("cli: a Blender render replays with and without composite; outputs carry its frame numbers"
  PROPERTIES LABELS gpu FIXTURES_REQUIRED cli_samples)
glint_cli_test(NAME "run's help says the capture is one path, a foreign EXR or a folder of them" LABELS unit EXIT 0
  STDOUT "capture.*with --map one foreign EXR or a folder of them"
  COMMAND run --help)
find_program(GLINT_PYTHON3 NAMES python3)
if(GLINT_PYTHON3)
  add_test(NAME "cli: docs/replay.md's camera recipe turns a plain camera JSON into a capture that replays"
    COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DPYTHON=${GLINT_PYTHON3}"
            "-DDOC=${PROJECT_SOURCE_DIR}/docs/replay.md" "-DSAMPLE=${GLINT_CLI_SAMPLE_DIR}/blender_plain"
            "-DMAP=${GLINT_BLENDER_MAP}" "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/camera_recipe"
            -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/camera_recipe.cmake")
  set_tests_properties("cli: docs/replay.md's camera recipe turns a plain camera JSON into a capture that replays"
    PROPERTIES LABELS gpu FIXTURES_REQUIRED cli_samples)
endif()
