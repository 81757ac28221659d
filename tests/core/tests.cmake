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
  LIBS glint_vulkan glint_internal)
