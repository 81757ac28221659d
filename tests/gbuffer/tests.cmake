# Roughness extraction: the pass on its own (gpu) and the whole path from a capture file (e2e).
glint_add_test_suite(NAME gbuffer LABELS gpu
  SOURCES
    gbuffer/extract_roughness_test.cpp
    gbuffer/pass_chaining_test.cpp
    gbuffer/roughness_runner.cpp
  LIBS glint_gpu_test_support glint_gpu)
glint_add_test_suite(NAME gbuffer_e2e LABELS e2e
  SOURCES
    gbuffer/capture_to_roughness_test.cpp
    gbuffer/roughness_runner.cpp
  LIBS glint_gpu_test_support glint_gpu glint_capture glint_replay)
