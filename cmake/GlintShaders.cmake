# HLSL -> SPIR-V for glint.
#
#   glint_add_hlsl_shader(NAME <name> ENTRY <file.cs.hlsl> [GROUP <group>]
#                         [DEFINES <D=V>...] [PERMUTATIONS "<suffix>:<D=V>[,<D=V>...]"...]
#                         [PROFILE <cs_6_x>] [TARGET_ENV <vulkan1.x>] [DXC_ONLY])
#
# compiles <file> with DXC when GLINT_DXC is set (or dxc is on PATH) and with glslang's HLSL
# front end otherwise, validates every module with spirv-val, and records each output so that
# glint_embed_shaders() can bake them into the host library. A permutation produces a second
# module "<name>.<suffix>" with the base defines plus its own. A DXC_ONLY module (one glslang
# cannot compile) is built only when DXC builds glint; the DXC tests compile it either way. The library's shaders and their
# permutations are listed in one place, hlsl/CMakeLists.txt (group "glint", embedded into
# glint_core); harness-only shaders use their own group and table (harness/shaders).
#
#   glint_check_hlsl_header(<header> [STUBS <stub.hlsl>])
#
# compiles one library header on its own (optionally with a stub file that defines its
# callbacks and calls its entry function) so that a header that only compiles after some
# other include is caught.

set(GLINT_HLSL_ROOT "${PROJECT_SOURCE_DIR}/hlsl")
set(GLINT_SPIRV_DIR "${PROJECT_BINARY_DIR}/spirv")
set(GLINT_GLSL_DIR "${PROJECT_BINARY_DIR}/glsl")
set(GLINT_SPIRV_TARGET_ENV vulkan1.1)

# The compile command line for one module, for whichever compiler is in use.
function(_glint_hlsl_command out_var input output depfile defines)
  # Optional ARGV5/ARGV6: the shader profile and SPIR-V environment of a module that needs more
  # than the library's cs_6_2 / vulkan1.1 (DXC only).
  set(profile cs_6_2)
  set(env ${GLINT_SPIRV_TARGET_ENV})
  if(ARGC GREATER 5 AND ARGV5)
    set(profile ${ARGV5})
  endif()
  if(ARGC GREATER 6 AND ARGV6)
    set(env ${ARGV6})
  endif()
  set(defs "")
  foreach(d IN LISTS defines)
    list(APPEND defs "-D${d}")
  endforeach()
  if(GLINT_DXC)
    set(cmd "${GLINT_DXC}" -spirv -fspv-target-env=${env} -HV 2021 -WX
            -T ${profile} -E main -enable-16bit-types -I "${GLINT_HLSL_ROOT}" -DGLINT_COMPILER_DXC=1
            ${defs} -Fo "${output}" "${input}")
  else()
    set(cmd "${GLINT_GLSLANG}" -V -D --target-env ${GLINT_SPIRV_TARGET_ENV} -S comp -e main
            --hlsl-enable-16bit-types -I${GLINT_HLSL_ROOT} -DGLINT_COMPILER_GLSLANG=1 ${defs}
            --depfile "${depfile}" -o "${output}" "${input}")
  endif()
  set(${out_var} "${cmd}" PARENT_SCOPE)
endfunction()

# The reflection file and GLSL 450 translation installed next to a library module
# (cmake/GlintShaderData.cmake says what they hold).
function(_glint_shader_data name input spirv defines)
  set(json "${GLINT_SPIRV_DIR}/${name}.json")
  set(glsl "${GLINT_GLSL_DIR}/${name}.comp")
  cmake_path(RELATIVE_PATH input BASE_DIRECTORY "${GLINT_HLSL_ROOT}" OUTPUT_VARIABLE source)
  if(GLINT_DXC)
    set(compiler dxc)
  else()
    set(compiler glslang)
  endif()
  add_custom_command(
    OUTPUT "${json}" "${glsl}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${GLINT_GLSL_DIR}"
    COMMAND "${CMAKE_COMMAND}" "-DSPIRV=${spirv}" "-DNAME=${name}" "-DSOURCE=${source}"
            "-DDEFINES=${defines}" "-DCOMPILER=${compiler}" "-DSPIRV_CROSS=${GLINT_SPIRV_CROSS_CLI}"
            "-DGLSLANG=${GLINT_GLSLANG}" "-DJSON_OUT=${json}" "-DGLSL_OUT=${glsl}"
            -P "${PROJECT_SOURCE_DIR}/cmake/GlintShaderData.cmake"
    DEPENDS "${spirv}" "${PROJECT_SOURCE_DIR}/cmake/GlintShaderData.cmake"
    COMMENT "Reflection and GLSL 450 of ${name}"
    VERBATIM)
  set_property(GLOBAL APPEND PROPERTY GLINT_SHADER_DATA_FILES "${json}" "${glsl}")
  set_property(GLOBAL APPEND PROPERTY GLINT_SHADER_REFLECTION_FILES "${json}")
  set_property(GLOBAL APPEND PROPERTY GLINT_SHADER_GLSL_FILES "${glsl}")
endfunction()

# Every module, permutation and header check is also recorded as one line
# "<kind>|<name>|<input>|<D=V>,...|<profile>|<env>" in the global property GLINT_DXC_RECIPES,
# whichever compiler builds glint: the DXC tests (cmake/GlintDxcTests.cmake) compile each one
# with DXC. <kind> is the entry's folder under hlsl/entry ("harness" for the harness's shaders,
# "header" for the header checks).
function(_glint_record_dxc_recipe name input defines profile env)
  if(NOT profile)
    set(profile cs_6_2)
  endif()
  if(NOT env)
    set(env ${GLINT_SPIRV_TARGET_ENV})
  endif()
  cmake_path(GET input PARENT_PATH folder)
  cmake_path(GET folder FILENAME kind)
  if(NOT input MATCHES "^${GLINT_HLSL_ROOT}/entry/")
    set(kind harness)
  endif()
  string(REPLACE ";" "," defs "${defines}")
  set_property(GLOBAL APPEND PROPERTY GLINT_DXC_RECIPES "${kind}|${name}|${input}|${defs}|${profile}|${env}")
endfunction()

function(_glint_compile_module name input defines group)
  # ARGVn past ARGC would read the caller's variables: check the count.
  set(profile "")
  set(env "")
  if(ARGC GREATER 4)
    set(profile "${ARGV4}")
  endif()
  if(ARGC GREATER 5)
    set(env "${ARGV5}")
  endif()
  if(NOT env)
    set(env ${GLINT_SPIRV_TARGET_ENV})
  endif()
  _glint_record_dxc_recipe("${name}" "${input}" "${defines}" "${profile}" "${env}")
  set(output "${GLINT_SPIRV_DIR}/${name}.spv")
  set(depfile "${GLINT_SPIRV_DIR}/${name}.d")
  _glint_hlsl_command(cmd "${input}" "${output}" "${depfile}" "${defines}" "${profile}" "${env}")
  set(extra "")
  if(NOT GLINT_DXC)
    set(extra DEPFILE "${depfile}")
  endif()
  add_custom_command(
    OUTPUT "${output}"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${GLINT_SPIRV_DIR}"
    COMMAND ${cmd}
    COMMAND "${GLINT_SPIRV_VAL}" --target-env ${env} "${output}"
    DEPENDS "${input}" ${GLINT_HLSL_HEADERS}
    ${extra}
    COMMENT "HLSL -> SPIR-V ${name}"
    VERBATIM)
  if(group STREQUAL "glint" AND GLINT_SPIRV_CROSS_CLI)
    _glint_shader_data("${name}" "${input}" "${output}" "${defines}")
  endif()
  set_property(GLOBAL APPEND PROPERTY GLINT_SHADER_NAMES_${group} "${name}")
  set_property(GLOBAL APPEND PROPERTY GLINT_SHADER_FILES_${group} "${output}")
  set_property(GLOBAL APPEND PROPERTY GLINT_SHADER_FILES "${output}")
endfunction()

function(glint_add_hlsl_shader)
  cmake_parse_arguments(ARG "DXC_ONLY" "NAME;ENTRY;GROUP;PROFILE;TARGET_ENV" "DEFINES;PERMUTATIONS" ${ARGN})
  if(NOT ARG_GROUP)
    set(ARG_GROUP glint)
  endif()
  if(NOT ARG_NAME OR NOT ARG_ENTRY)
    message(FATAL_ERROR "glint_add_hlsl_shader needs NAME and ENTRY")
  endif()
  cmake_path(ABSOLUTE_PATH ARG_ENTRY BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  if(ARG_DXC_ONLY AND NOT GLINT_DXC)
    # Built by glslang, a DXC-only module is only recorded for the DXC tests.
    _glint_record_dxc_recipe("${ARG_NAME}" "${ARG_ENTRY}" "${ARG_DEFINES}" "${ARG_PROFILE}" "${ARG_TARGET_ENV}")
    return()
  endif()
  _glint_compile_module("${ARG_NAME}" "${ARG_ENTRY}" "${ARG_DEFINES}" "${ARG_GROUP}" "${ARG_PROFILE}"
                        "${ARG_TARGET_ENV}")
  foreach(perm IN LISTS ARG_PERMUTATIONS)
    string(FIND "${perm}" ":" colon)
    if(colon LESS 1)
      message(FATAL_ERROR "permutation '${perm}' of ${ARG_NAME} must read <suffix>:<D=V>,...")
    endif()
    string(SUBSTRING "${perm}" 0 ${colon} suffix)
    math(EXPR start "${colon} + 1")
    string(SUBSTRING "${perm}" ${start} -1 perm_defs)
    string(REPLACE "," ";" perm_defs "${perm_defs}")
    set(all_defs ${ARG_DEFINES} ${perm_defs})
    _glint_compile_module("${ARG_NAME}.${suffix}" "${ARG_ENTRY}" "${all_defs}" "${ARG_GROUP}" "${ARG_PROFILE}"
                          "${ARG_TARGET_ENV}")
  endforeach()
endfunction()

# Generates <target>'s embedded shader table for one group: a C++ source in the build tree
# holding each module as a uint32_t array, plus a sorted name -> span index, defining
#   std::span<const std::uint32_t> <NAMESPACE>::findShader(std::string_view)
#   std::vector<std::string_view> <NAMESPACE>::shaderNames()
function(glint_embed_shaders target)
  cmake_parse_arguments(ARG "" "GROUP;NAMESPACE;HEADER" "" ${ARGN})
  get_property(names GLOBAL PROPERTY GLINT_SHADER_NAMES_${ARG_GROUP})
  get_property(files GLOBAL PROPERTY GLINT_SHADER_FILES_${ARG_GROUP})
  set(generated "${PROJECT_BINARY_DIR}/generated/${ARG_GROUP}_embedded_shaders.cpp")
  add_custom_command(
    OUTPUT "${generated}"
    COMMAND "${CMAKE_COMMAND}" "-DNAMES=${names}" "-DFILES=${files}" "-DOUTPUT=${generated}"
            "-DNAMESPACE=${ARG_NAMESPACE}" "-DHEADER=${ARG_HEADER}"
            -P "${PROJECT_SOURCE_DIR}/cmake/GlintEmbedSpirv.cmake"
    DEPENDS ${files} "${PROJECT_SOURCE_DIR}/cmake/GlintEmbedSpirv.cmake"
    COMMENT "Embedding SPIR-V modules of group ${ARG_GROUP}"
    VERBATIM)
  target_sources(${target} PRIVATE "${generated}")
endfunction()

function(glint_check_hlsl_header header)
  cmake_parse_arguments(ARG "" "STUBS" "" ${ARGN})
  cmake_path(ABSOLUTE_PATH header BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  cmake_path(GET header STEM stem)
  set(check_src "${PROJECT_BINARY_DIR}/hlsl_check/${stem}.check.hlsl")
  # glslang resolves includes only through its search path, so name files relative to hlsl/.
  file(RELATIVE_PATH header_rel "${GLINT_HLSL_ROOT}" "${header}")
  set(body "// Generated: compiles ${header_rel} alone.\n#include \"${header_rel}\"\n")
  if(ARG_STUBS)
    cmake_path(ABSOLUTE_PATH ARG_STUBS BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
    file(RELATIVE_PATH stubs_rel "${GLINT_HLSL_ROOT}" "${ARG_STUBS}")
    string(APPEND body "#include \"${stubs_rel}\"\n")
  else()
    string(APPEND body "[numthreads(1, 1, 1)] void main() {}\n")
  endif()
  file(GENERATE OUTPUT "${check_src}" CONTENT "${body}")
  set(output "${PROJECT_BINARY_DIR}/hlsl_check/${stem}.spv")
  set_property(GLOBAL APPEND PROPERTY GLINT_DXC_RECIPES
    "header|${stem}|${check_src}|GLINT_HEADER_CHECK=1|cs_6_2|${GLINT_SPIRV_TARGET_ENV}")
  _glint_hlsl_command(cmd "${check_src}" "${output}" "${output}.d" "GLINT_HEADER_CHECK=1")
  string(REPLACE ";" "|" strict "${cmd}")
  add_custom_command(
    OUTPUT "${output}"
    COMMAND "${CMAKE_COMMAND}" "-DCOMMAND=${strict}" -P "${PROJECT_SOURCE_DIR}/cmake/GlintStrictCompile.cmake"
    COMMAND "${GLINT_SPIRV_VAL}" --target-env ${GLINT_SPIRV_TARGET_ENV} "${output}"
    DEPENDS "${header}" ${ARG_STUBS} ${GLINT_HLSL_CHECK_STUBS} ${GLINT_HLSL_HEADERS}
    COMMENT "HLSL header check ${stem}"
    VERBATIM)
  set_property(GLOBAL APPEND PROPERTY GLINT_HLSL_CHECK_OUTPUTS "${output}")
endfunction()
