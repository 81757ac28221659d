# SSSR: the plan (unit) and the passes on the device (gpu) against the CPU references in
# tests/reference/sssr_reference.*. The tables, VNDF and reference self-tests have their own
# fragments (tables.cmake, vndf.cmake, reference.cmake).
glint_add_test_suite(NAME sssr_unit LABELS unit
  SOURCES sssr/plan_test.cpp
  LIBS glint_core)

glint_add_test_suite(NAME sssr LABELS gpu
  SOURCES
    sssr/classify_test.cpp
    sssr/traversal_test.cpp
    sssr/hard_cases_test.cpp
    sssr/composite_test.cpp
    sssr/previous_frame_test.cpp
    sssr/sssr_test_scene.cpp
    sssr/sssr_classify_view.cpp
    reference/sssr_reference.cpp
  LIBS glint_test_runners glint_internal glint_gpu_test_support glint_gpu)

# SSSR on simulated scenes (simulator: harness/scene): the multi-frame average against
# reference.reflection, and half-resolution coverage and stability.
glint_add_test_suite(NAME sssr_scene LABELS gpu
  SOURCES sssr/convergence_test.cpp
  LIBS glint_test_replay glint_replay glint_scene glint_gpu_test_support glint_gpu)
