# glint run, dump, check and report: end to end on small simulated captures with golden-free
# checks (the error against the capture's own reference, and the denoised output against its
# noisy input), a dump/check round trip, and the errors a user can make.
glint_cli_test(NAME "run replays the sample capture under validation" LABELS gpu EXIT 0
  STDOUT "effects: reflections.*reflections/classify.*reflections/intersect.*wrote .*summary.json"
  COMMAND --validate run "${GLINT_CLI_SAMPLE_DIR}/sample" --out "${PROJECT_BINARY_DIR}/test-output/cli/run_sample")
glint_cli_test(NAME "run on a missing capture prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "does_not_exist: no such file or folder"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/does_not_exist" --out "${PROJECT_BINARY_DIR}/test-output/cli/run_missing")
# Errors before output (issue 24, item 2): the bad frame is found before frame 0 is written.
add_test(NAME "cli: run with a truncated last frame fails in one line before writing anything"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DCAPTURE=${GLINT_CLI_SAMPLE_DIR}/truncated_last_frame"
          "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/run_truncated_last"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/nothing_written.cmake")
set_tests_properties("cli: run with a truncated last frame fails in one line before writing anything"
                     PROPERTIES LABELS "unit" FIXTURES_REQUIRED cli_samples)
glint_cli_test(NAME "run on a truncated capture prints one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "truncated.exr"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/truncated.exr" --out "${PROJECT_BINARY_DIR}/test-output/cli/run_truncated")
glint_cli_test(NAME "run of an effect the capture cannot feed names the missing layer" LABELS gpu EXIT 2
  STDERR_ONE_LINE "effect 'shadows' needs the capture layer 'shadow'.*docs/capture-format.md, .Required layers.; from Blender: docs/replay.md, .Shadow visibility from Blender.$"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --effects shadows --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "run of an unknown effect is a usage error" LABELS gpu EXIT 2
  STDERR_ONE_LINE "unknown effect 'nosuch'"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --effects reflections,nosuch --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "run with frames outside the capture is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "--frames 1..7 is outside the capture's 2 frame"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --frames 1..7 --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "run with an unknown setting is a usage error naming it" LABELS unit EXIT 2
  STDERR_ONE_LINE "unknown setting 'nosuch'"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --set nosuch=1 --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "run with an unknown shadow output format is a usage error naming the formats" LABELS unit EXIT 2
  STDERR_ONE_LINE "shadows.outputFormat needs r8, r16f or rg32f, got 'rgba32f'"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --set shadows.outputFormat=rgba32f --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "dump of a pass the replay does not have is a usage error" LABELS gpu EXIT 2
  STDERR_ONE_LINE "no pass named 'nosuch'"
  COMMAND dump "${GLINT_CLI_SAMPLE_DIR}/sample" --pass nosuch --out "${PROJECT_BINARY_DIR}/test-output/cli/dump_bad")
glint_cli_test(NAME "check against a missing folder is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "no_such_dir: no such folder"
  COMMAND check "${GLINT_CLI_SAMPLE_DIR}/sample" --expected "${GLINT_CLI_SAMPLE_DIR}/no_such_dir")
glint_cli_test(NAME "report without summary.json names the file" LABELS unit EXIT 2
  STDERR_ONE_LINE "summary.json is missing"
  COMMAND report "${GLINT_CLI_SAMPLE_DIR}" --out "${PROJECT_BINARY_DIR}/test-output/cli/report_bad.html")

# Simulated scenes with references through run (bounds in replay_e2e.cmake), then dump/check.
foreach(case IN ITEMS reflections shadows movingedges roundtrip unscored noisefloor)
  add_test(NAME "cli: replay end to end: ${case}"
    COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DCASE=${case}"
            "-DSCENES=${PROJECT_SOURCE_DIR}/harness/scenes" "-DCASES=${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes"
            "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/replay_${case}"
            -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/replay_e2e.cmake")
  set_tests_properties("cli: replay end to end: ${case}" PROPERTIES LABELS gpu)
endforeach()
add_test(NAME "cli: hybrid end to end: the mirror corridor at half SSSR's error, a capture without its scene refused"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DSCENES=${PROJECT_SOURCE_DIR}/harness/scenes"
          "-DSAMPLE=${GLINT_CLI_SAMPLE_DIR}/sample" "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/hybrid"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/hybrid_e2e.cmake")
set_tests_properties("cli: hybrid end to end: the mirror corridor at half SSSR's error, a capture without its scene refused"
  PROPERTIES LABELS gpu FIXTURES_REQUIRED cli_samples)

# --geometry FILE (docs/replay.md): a glTF for the effects that ray trace a capture without a
# scene. glint_export_geometry writes a scene file's geometry as glTF (tests/scene/scene_gltf_export.h).
add_executable(glint_export_geometry cli/export_geometry.cpp scene/scene_gltf_export.cpp)
target_link_libraries(glint_export_geometry PRIVATE glint_scene)
target_include_directories(glint_export_geometry PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}")
glint_target_defaults(glint_export_geometry)
add_test(NAME "cli: geometry end to end: the hybrid with --geometry equals the hybrid with the manifest's scene"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DEXPORT=$<TARGET_FILE:glint_export_geometry>"
          "-DSCENE=${CMAKE_CURRENT_SOURCE_DIR}/cli/scenes/geometry_corridor.toml"
          "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/geometry" -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/geometry_e2e.cmake")
set_tests_properties("cli: geometry end to end: the hybrid with --geometry equals the hybrid with the manifest's scene"
  PROPERTIES LABELS gpu)
set(GLINT_GEOMETRY_DIR "${CMAKE_CURRENT_SOURCE_DIR}/data/geometry")
glint_cli_test(NAME "run --geometry with a missing file prints one line naming it and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: [^ ]*no_such_geometry.gltf: no such file$"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --effects hybrid --geometry "${GLINT_GEOMETRY_DIR}/no_such_geometry.gltf"
          --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "run --geometry with a malformed glTF prints one line naming it and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: [^ ]*malformed.gltf: cannot read as a model: malformed glTF JSON: line 3, column 1: "
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --effects hybrid --geometry "${GLINT_GEOMETRY_DIR}/malformed.gltf"
          --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")
glint_cli_test(NAME "dump --geometry with a glTF without triangles prints one line naming it and exits 2" LABELS unit
  EXIT 2
  STDERR_ONE_LINE "^glint: [^ ]*points_only.gltf: no triangles"
  COMMAND dump "${GLINT_CLI_SAMPLE_DIR}/sample" --effects hybrid --geometry "${GLINT_GEOMETRY_DIR}/points_only.gltf"
          --out "${PROJECT_BINARY_DIR}/test-output/cli/dump_bad")
glint_cli_test(NAME "check --geometry with a binary glTF whose chunk overruns the file prints one line and exits 2"
  LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: [^ ]*assimp-glb-json-chunk-2.1GB.glb: cannot read as a model: binary glTF "
  COMMAND check "${GLINT_CLI_SAMPLE_DIR}/sample" --effects hybrid --expected "${GLINT_CLI_SAMPLE_DIR}"
          --geometry "${CMAKE_CURRENT_SOURCE_DIR}/fuzz/third_party_crashes/gltf/assimp-glb-json-chunk-2.1GB.glb")
glint_cli_test(NAME "bench --geometry with a folder prints one line naming it and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: [^ ]*geometry: is a folder, not a model file$"
  COMMAND bench "${GLINT_CLI_SAMPLE_DIR}/sample" --runs 1 --geometry "${GLINT_GEOMETRY_DIR}")
glint_cli_test(NAME "run with a missing channel map names the map file" LABELS unit EXIT 2
  STDERR_ONE_LINE "no_such_map.toml"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --map "${GLINT_CLI_SAMPLE_DIR}/no_such_map.toml"
          --out "${PROJECT_BINARY_DIR}/test-output/cli/run_bad")

# The report's metric sentence, error-against-frame plot and anchors (no GPU: a hand-written run).
add_test(NAME "cli: report names the metric, plots error against frame and lists anchors beside the plot"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>"
          "-DANCHORS=${PROJECT_SOURCE_DIR}/docs/anchors/fidelityfx-sdk-1.1.4.json"
          "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/report_plot" -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/report_plot.cmake")
set_tests_properties("cli: report names the metric, plots error against frame and lists anchors beside the plot"
  PROPERTIES LABELS unit)

# scripts/run_flip.py (docs/replay.md, "FLIP of a run"): its value tests, then LDR-FLIP per frame of
# two small runs and the report's FLIP columns and plots. Needs build/venv (python_env_check.cmake).
add_test(NAME "cli: run_flip.py adds LDR-FLIP per frame to glint run folders and report shows it"
  COMMAND "${CMAKE_COMMAND}" "-DGLINT=$<TARGET_FILE:glint>" "-DPYTHON=${PROJECT_SOURCE_DIR}/build/venv/bin/python"
          "-DSCRIPT=${PROJECT_SOURCE_DIR}/scripts/run_flip.py" "-DSCRIPTS=${PROJECT_SOURCE_DIR}/scripts"
          "-DVALUE_TESTS=${CMAKE_CURRENT_SOURCE_DIR}/cli/run_flip_test.py"
          "-DSCENES=${PROJECT_SOURCE_DIR}/harness/scenes" "-DOUT=${PROJECT_BINARY_DIR}/test-output/cli/run_flip"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/cli/run_flip.cmake")
set_tests_properties("cli: run_flip.py adds LDR-FLIP per frame to glint run folders and report shows it"
  PROPERTIES LABELS gpu SKIP_REGULAR_EXPRESSION "SKIP:")
