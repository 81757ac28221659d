# Hybrid reflections on the device against the CPU references in tests/reference/hybrid_*.
glint_add_test_suite(NAME hybrid LABELS gpu
  SOURCES
    hybrid/classify_test.cpp
    hybrid/intersect_test.cpp
    hybrid/trace_test.cpp
    hybrid/composed_test.cpp
    hybrid/scene_test.cpp
    hybrid/sequence_test.cpp
    hybrid/hybrid_test_frame.cpp
    sssr/sssr_test_scene.cpp
    sssr/sssr_classify_view.cpp
    reference/sssr_reference.cpp
    reference/hybrid_classify_reference.cpp
  LIBS glint_test_runners glint_test_replay glint_replay glint_internal glint_gpu_test_support glint_gpu glint_scene)
