# Reflections denoiser: the plan (unit) and SSSR + denoiser on simulated scenes (gpu).
glint_add_test_suite(NAME reflections_denoiser LABELS gpu
  SOURCES
    reflections_denoiser/non_finite_test.cpp
    reflections_denoiser/ghosting_test.cpp
    reflections_denoiser/hdr_highlight_test.cpp
    reflections_denoiser/mirror_test.cpp
    reflections_denoiser/repeat_test.cpp
    reflections_denoiser/denoiser_scene.cpp
    reflections_denoiser/reference_test.cpp
    reflections_denoiser/ratio_test.cpp
    reflections_denoiser/ratio_scene_test.cpp
    reference/reflections_denoiser_reference.cpp
    reference/reflections_denoiser_ratio_reference.cpp
  LIBS glint_test_replay glint_replay glint_scene glint_gpu_test_support glint_gpu)

glint_add_test_suite(NAME reflections_denoiser_unit LABELS unit
  SOURCES reflections_denoiser/plan_test.cpp
  LIBS glint_core)
