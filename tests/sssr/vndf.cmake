# GGX VNDF sampling (hlsl/glint/common/glint_ggx.hlsli) on the device, through the harness
# shader test_ggx_sample, against double-precision densities on the CPU (chi-square).
glint_add_test_suite(NAME sssr_vndf LABELS gpu
  SOURCES sssr/vndf_test.cpp
  LIBS glint_scene glint_gpu_test_support glint_gpu)
# The expected bin probabilities integrate the densities over millions of directions per
# case; keep that fast in Debug (sanitizers stay on), as harness/scene does for its BVH.
set_source_files_properties(sssr/vndf_test.cpp PROPERTIES COMPILE_OPTIONS "-O2" SKIP_PRECOMPILE_HEADERS ON)
