# Every dependency comes from the distribution's packages (see scripts/setup.sh).
# Nothing here touches the network.
if(GLINT_BUILD_VULKAN)
  find_package(Vulkan 1.3 REQUIRED)
  find_package(spirv_cross_core CONFIG REQUIRED)
  find_package(spirv_cross_reflect CONFIG QUIET)
endif()

find_program(GLINT_GLSLANG NAMES glslangValidator glslang REQUIRED)
find_program(GLINT_SPIRV_VAL NAMES spirv-val REQUIRED)
find_program(GLINT_SPIRV_OPT NAMES spirv-opt)
# SPIRV-Cross's command-line tool writes the installed reflection files and GLSL 450
# translations of the library's modules; without it the package ships SPIR-V only.
find_program(GLINT_SPIRV_CROSS_CLI NAMES spirv-cross)
if(NOT GLINT_SPIRV_CROSS_CLI)
  message(STATUS "glint: spirv-cross not found; no reflection files or GLSL 450 translations")
endif()
# With the DXC tests configured (GLINT_DXC_TESTS, as scripts/test.sh does) glint itself is built
# by glslang unless GLINT_DXC says otherwise, so that the suites run on both compilers' SPIR-V.
if(NOT GLINT_DXC AND NOT GLINT_DXC_TESTS)
  find_program(GLINT_DXC_FOUND NAMES dxc)
  if(GLINT_DXC_FOUND)
    set(GLINT_DXC "${GLINT_DXC_FOUND}")
  endif()
endif()
if(GLINT_DXC)
  message(STATUS "glint: HLSL compiler is DXC (${GLINT_DXC})")
else()
  message(STATUS "glint: HLSL compiler is glslang (${GLINT_GLSLANG}); set GLINT_DXC to use DXC")
endif()

if(GLINT_BUILD_HARNESS)
  find_package(OpenEXR CONFIG REQUIRED)
  find_package(CLI11 CONFIG REQUIRED)
  find_package(nlohmann_json CONFIG REQUIRED)
  find_package(tomlplusplus CONFIG QUIET)
endif()
if(GLINT_BUILD_TESTS)
  find_package(Catch2 2 CONFIG REQUIRED)
endif()
