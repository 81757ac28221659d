# GPU harness tests. gpu_unit needs no device; gpu runs on the device GLINT_DEVICE selects
# (lavapipe in CI) under the validation layer.

# The shared validated context and GLINT_REQUIRE_NO_VALIDATION_ERRORS for every GPU suite.
add_library(glint_gpu_test_support STATIC support/gpu_test_context.cpp)
target_link_libraries(glint_gpu_test_support PUBLIC glint_gpu Catch2::Catch2)
target_include_directories(glint_gpu_test_support PUBLIC "${CMAKE_CURRENT_SOURCE_DIR}")
glint_target_defaults(glint_gpu_test_support)

glint_add_test_suite(NAME gpu_unit LABELS unit
  SOURCES
    gpu/device_choice_test.cpp
    gpu/half_test.cpp
    gpu/texel_format_test.cpp
    gpu/timestamp_math_test.cpp
  LIBS glint_gpu)

glint_add_test_suite(NAME gpu LABELS gpu HARNESS_SHADERS_ONLY
  SOURCES
    gpu/buffer_transfer_test.cpp
    gpu/context_test.cpp
    gpu/effect_limits_test.cpp
    gpu/image_transfer_test.cpp
    gpu/sustained_test.cpp
    gpu/timestamps_test.cpp
    gpu/validation_test.cpp
  LIBS glint_gpu_test_support)
