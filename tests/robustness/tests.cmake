# Long hard sequences (issue 24, item 3): every effect over 225 frames of each hard case, with
# NaN/Inf/denormals injected into inputs and histories; labelled slow.
glint_add_test_suite(NAME robustness LABELS gpu slow
  SOURCES
    robustness/long_sequence_test.cpp
    robustness/robust_effects.cpp
    robustness/robust_cases.cpp
  LIBS glint_replay glint_gpu_test_support glint_gpu glint_scene)
