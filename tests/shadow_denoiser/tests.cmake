# Shadow denoiser: the plan and the CPU packer (unit), and the passes on the device (gpu)
# against the CPU references.
glint_add_test_suite(NAME shadow_denoiser_unit LABELS unit
  SOURCES
    shadow_denoiser/plan_test.cpp
    reference/shadow_denoiser_reference.cpp
  LIBS glint_core glint_internal)

glint_add_test_suite(NAME shadow_denoiser LABELS gpu
  SOURCES
    shadow_denoiser/prepare_test.cpp
    shadow_denoiser/filter_test.cpp
    shadow_denoiser/classify_test.cpp
    shadow_denoiser/output_format_test.cpp
    reference/shadow_classify_independent.cpp
    shadow_denoiser/shadow_runner.cpp
    reference/shadow_denoiser_reference.cpp
  LIBS glint_test_runners glint_gpu_test_support glint_gpu)

# The denoiser on simulated scenes (simulator: harness/scene): a static one converges, a moving
# occluder and a moving light are followed, the bundled moving scenes stay at or below their input.
glint_add_test_suite(NAME shadow_denoiser_scene LABELS gpu
  SOURCES
    shadow_denoiser/convergence_test.cpp
    shadow_denoiser/tracking_test.cpp
    shadow_denoiser/penumbra_measure_test.cpp
    shadow_denoiser/penumbra_scene_test.cpp
    shadow_denoiser/moving_scene_test.cpp
    shadow_denoiser/scene_replay.cpp
    shadow_denoiser/shadow_runner.cpp
  LIBS glint_test_replay glint_replay glint_scene glint_gpu_test_support glint_gpu)
