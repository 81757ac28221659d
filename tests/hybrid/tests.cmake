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

# The engines' RayQuery entry against the BVH tracer (rayquery_test.cpp): its module comes from
# the DXC build of every module (fixture dxc_spirv), and it runs on Mesa 25's lavapipe from
# bookworm-backports, which scripts/setup.sh unpacks beside the system's (CONTRIBUTING.md).
if(GLINT_DXC_TESTS)
  set(GLINT_RAYQUERY_LAVAPIPE "${PROJECT_SOURCE_DIR}/build/lavapipe-rayquery" CACHE PATH
      "folder holding the ray-query lavapipe (scripts/lavapipe_rayquery.sh)")
  glint_add_test_suite(NAME hybrid_rayquery LABELS gpu rayquery
    SOURCES
      hybrid/rayquery_test.cpp
      hybrid/hybrid_test_frame.cpp
      sssr/sssr_test_scene.cpp
    LIBS glint_test_runners glint_test_replay glint_replay glint_internal glint_gpu_test_support glint_gpu glint_scene)
  set(label_file "${CMAKE_CURRENT_BINARY_DIR}/glint_tests_hybrid_rayquery_environment.cmake")
  file(WRITE "${label_file}"
    "if(DEFINED glint_tests_hybrid_rayquery_TESTS)\n"
    "  set_tests_properties(\${glint_tests_hybrid_rayquery_TESTS} PROPERTIES\n"
    "    ENVIRONMENT \"GLINT_SHADER_DIR=${GLINT_DXC_SPIRV_DIR};VK_DRIVER_FILES=${GLINT_RAYQUERY_LAVAPIPE}/lvp_icd.json;LD_LIBRARY_PATH=${GLINT_RAYQUERY_LAVAPIPE}/lib\"\n"
    "    FIXTURES_REQUIRED dxc_spirv)\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${label_file}")
endif()
