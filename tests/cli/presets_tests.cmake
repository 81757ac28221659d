# Presets (docs/accuracy-vs-time.md, "Presets"): the rules on hand-made inputs, then --preset as
# the verbs take it. glint_cli_test comes from cli/tests.cmake.
glint_add_test_suite(NAME cli_presets LABELS unit SOURCES cli/presets_test.cpp LIBS glint_cli_support)

set(GLINT_PRESET_OUT "${PROJECT_BINARY_DIR}/test-output/cli/presets")
# The sample declares reflections; the built-in medium gives them denoise=true and
# maxTraversalIterations=64, and --set follows, so its maxTraversalIterations=32 wins when parsed.
glint_cli_test(NAME "run applies the preset's settings for the capture's effects before --set" LABELS gpu EXIT 0
  STDOUT "\"preset\": *\"medium\".*\"settings\": *\\[ *\"denoise=true\", *\"maxTraversalIterations=64\", *\"maxTraversalIterations=32\" *\\]"
  COMMAND --validate run "${GLINT_CLI_SAMPLE_DIR}/sample" --preset medium --set maxTraversalIterations=32 --json
          --out "${GLINT_PRESET_OUT}/run_medium")
# --effects names what runs, so the preset's shadows bundle is the one applied.
glint_cli_test(NAME "bench applies the preset's bundle for the effects named with --effects" LABELS gpu EXIT 0
  STDOUT "\"settings\": *\\[ *\"shadows.filter=false\" *\\]"
  COMMAND --validate bench "${PROJECT_SOURCE_DIR}/harness/scenes/courtyard_penumbra.toml" --resolution 32x18
          --runs 2 --effects shadows --preset low --json -)
glint_cli_test(NAME "an unknown preset prints the known ones in one line and exits 2" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: unknown preset 'extreme' \\(low, medium, high, ultra\\)$"
  COMMAND run "${GLINT_CLI_SAMPLE_DIR}/sample" --preset extreme --out "${GLINT_PRESET_OUT}/run_bad")
glint_cli_test(NAME "a preset file without a preset is a usage error" LABELS unit EXIT 2
  STDERR_ONE_LINE "^glint: --preset-file p.toml needs --preset NAME$"
  COMMAND dump "${GLINT_CLI_SAMPLE_DIR}/sample" --preset-file p.toml --out "${GLINT_PRESET_OUT}/dump_bad")
# An effect named alone gets its own preset bundle, as a capture's effects do.
glint_cli_test(NAME "bench of an effect applies the preset's bundle for that effect" LABELS gpu EXIT 0
  STDOUT "\"settings\": *\\[ *\"shadows.filter=false\" *\\]"
  COMMAND --validate bench shadows --scene "${PROJECT_SOURCE_DIR}/harness/scenes/courtyard_penumbra.toml"
          --resolution 32x18 --runs 2 --preset low --json -)
