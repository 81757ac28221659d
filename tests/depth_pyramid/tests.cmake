# Depth pyramid: the plan and the CPU reference (unit), and the pass on the device (gpu)
# against the reference bit for bit and against the property checker.
glint_add_test_suite(NAME depth_pyramid_unit LABELS unit
  SOURCES
    depth_pyramid/plan_test.cpp
    depth_pyramid/reference_test.cpp
    depth_pyramid/depth_inputs.cpp
    reference/depth_pyramid_reference.cpp
  LIBS glint_core glint_internal)

# The reference and its brute-force checker scan every level-0 pixel once per level; keep
# them fast in Debug (sanitizers stay on). Optimized, they cannot use the suites' precompiled
# header (built without -O2).
set_source_files_properties(reference/depth_pyramid_reference.cpp depth_pyramid/depth_inputs.cpp
  PROPERTIES COMPILE_OPTIONS "-O2" SKIP_PRECOMPILE_HEADERS ON)

glint_add_test_suite(NAME depth_pyramid LABELS gpu
  SOURCES
    depth_pyramid/exact_test.cpp
    depth_pyramid/non_finite_test.cpp
    depth_pyramid/race_test.cpp
    depth_pyramid/levels_test.cpp
    depth_pyramid/exact_4k_test.cpp
    depth_pyramid/pyramid_runner.cpp
    depth_pyramid/depth_inputs.cpp
    reference/depth_pyramid_reference.cpp
  LIBS glint_gpu_test_support glint_gpu)
