# DXC's tests, when GLINT_DXC_TESTS names a DXC (scripts/test.sh passes GLINT_DXC, or the dxc
# on PATH): whichever compiler built glint, ctest compiles every module and permutation with DXC
# under -WX to SPIR-V (validated) and to DXIL, one test per module kind and form, and every
# header check to SPIR-V. The library's and the engine entries' SPIR-V lands in
# GLINT_DXC_SPIRV_DIR (fixture dxc_spirv), where the GPU suites' "[dxc]" copies load those modules
# from (GLINT_SHADER_DIR, tests/CMakeLists.txt); the harness's own shaders (the simulator, the
# application's BVH tracer and shading) land in its harness/ folder, so the copies run them as
# glslang built them: they stand for the engine's side, and lavapipe's cache of their pipelines
# serves both runs.
set(GLINT_DXC_SPIRV_DIR "${PROJECT_BINARY_DIR}/spirv-dxc")
set(GLINT_DXC_DXIL_DIR "${PROJECT_BINARY_DIR}/dxil-dxc")
set(recipe_dir "${PROJECT_BINARY_DIR}/dxc-recipes")
get_property(recipes GLOBAL PROPERTY GLINT_DXC_RECIPES)
set(kinds "")
foreach(recipe IN LISTS recipes)
  string(REPLACE "|" ";" fields "${recipe}")
  list(GET fields 0 kind)
  list(APPEND kinds ${kind})
  string(APPEND recipes_${kind} "${recipe}\n")
endforeach()
list(REMOVE_DUPLICATES kinds)
foreach(kind IN LISTS kinds)
  file(WRITE "${recipe_dir}/${kind}.txt" "${recipes_${kind}}")
  if(kind STREQUAL "header")
    set(forms spirv)
    set(what "every library header check compiles alone with DXC to SPIR-V under -WX and validates")
  else()
    set(forms spirv dxil)
  endif()
  foreach(form IN LISTS forms)
    if(form STREQUAL "spirv")
      set(out "${GLINT_DXC_SPIRV_DIR}")
      if(kind STREQUAL "header" OR kind STREQUAL "harness")
        set(out "${GLINT_DXC_SPIRV_DIR}/${kind}")
      endif()
      if(NOT kind STREQUAL "header")
        set(what "${kind} modules and permutations compile with DXC to SPIR-V under -WX and validate")
      endif()
    else()
      set(out "${GLINT_DXC_DXIL_DIR}")
      set(what "${kind} modules and permutations compile with DXC to DXIL under -WX")
    endif()
    add_test(NAME "dxc: ${what}"
      COMMAND "${CMAKE_COMMAND}" "-DDXC=${GLINT_DXC_TESTS}" "-DSPIRV_VAL=${GLINT_SPIRV_VAL}"
              "-DLIST=${recipe_dir}/${kind}.txt" -DMODE=${form} "-DOUT_DIR=${out}"
              "-DHLSL_ROOT=${GLINT_HLSL_ROOT}" -P "${PROJECT_SOURCE_DIR}/cmake/GlintDxcCompile.cmake")
    set_tests_properties("dxc: ${what}" PROPERTIES LABELS "unit;dxc")
    if(form STREQUAL "spirv" AND NOT kind STREQUAL "header" AND NOT kind STREQUAL "harness")
      set_tests_properties("dxc: ${what}" PROPERTIES FIXTURES_SETUP dxc_spirv)
    endif()
  endforeach()
endforeach()
