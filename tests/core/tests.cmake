# Vulkan-free behaviour of the pass model: runs anywhere, no device needed.
glint_add_test_suite(NAME core LABELS unit
  SOURCES
    core/dispatch_sizing_test.cpp
    core/barrier_planning_test.cpp
    core/plan_validation_test.cpp
    core/shader_library_test.cpp
    core/constants_layout_test.cpp
    core/settings_test.cpp
    core/effect_registry_test.cpp
    core/view_depth_test.cpp
    core/shader_reflection_file_test.cpp
  LIBS glint_vulkan glint_internal nlohmann_json::nlohmann_json)
# The reflection files and GLSL translations are build outputs of the library's modules.
target_compile_definitions(glint_tests_core PRIVATE
  GLINT_TEST_SPIRV_DIR="${GLINT_SPIRV_DIR}" GLINT_TEST_GLSL_DIR="${GLINT_GLSL_DIR}"
  GLINT_TEST_HLSL_ROOT="${GLINT_HLSL_ROOT}")
add_dependencies(glint_tests_core glint_shaders)
