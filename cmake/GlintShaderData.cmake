# Script mode (cmake -P): the shader data installed next to one compiled module.
#   -DSPIRV=<module.spv> -DNAME=<module name> -DSOURCE=<entry file, relative to the HLSL root>
#   -DDEFINES=<D=V;...> -DCOMPILER=<dxc|glslang> -DSPIRV_CROSS=<spirv-cross> -DGLSLANG=<glslang>
#   -DJSON_OUT=<module.json> -DGLSL_OUT=<module.comp>
#
# <module.json>: what an engine binds and dispatches — entry file, permutation defines, thread
# shape, and every binding (set, slot, name, kind, storage format, access), with the member
# layout of each constant buffer. Read from the SPIR-V itself (SPIRV-Cross's reflection), so it
# describes the module as compiled, not as intended.
# <module.comp>: a GLSL 450 translation for OpenGL engines (SPIRV-Cross), checked by glslang.

foreach(var SPIRV NAME SOURCE COMPILER SPIRV_CROSS GLSLANG JSON_OUT GLSL_OUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "GlintShaderData.cmake needs -D${var}=...")
  endif()
endforeach()

execute_process(COMMAND "${SPIRV_CROSS}" "${SPIRV}" --reflect
                OUTPUT_VARIABLE reflection ERROR_VARIABLE error RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NAME}: spirv-cross --reflect failed: ${error}")
endif()

# A JSON string literal (the names here are identifiers and paths, so escaping quotes and
# backslashes is enough).
function(_glint_json_string out value)
  string(REPLACE "\\" "\\\\" value "${value}")
  string(REPLACE "\"" "\\\"" value "${value}")
  set(${out} "\"${value}\"" PARENT_SCOPE)
endfunction()

# The optional member <key> of <object>, or <default> when it is absent.
function(_glint_json_get out object key default)
  string(JSON value ERROR_VARIABLE missing GET "${object}" "${key}")
  if(missing)
    set(value "${default}")
  endif()
  set(${out} "${value}" PARENT_SCOPE)
endfunction()

# The members of struct <type_id>, nested structs flattened to "outer.inner" names with
# absolute offsets, as JSON objects.
function(_glint_flatten_members out type_id prefix base_offset)
  set(result "")
  string(JSON count LENGTH "${reflection}" types "${type_id}" members)
  math(EXPR last "${count} - 1")
  foreach(m RANGE ${last})
    string(JSON member GET "${reflection}" types "${type_id}" members ${m})
    string(JSON member_name GET "${member}" name)
    string(JSON member_type GET "${member}" type)
    string(JSON member_offset GET "${member}" offset)
    math(EXPR offset "${base_offset} + ${member_offset}")
    string(JSON nested ERROR_VARIABLE not_struct GET "${reflection}" types "${member_type}")
    if(NOT not_struct)
      _glint_flatten_members(inner "${member_type}" "${prefix}${member_name}." ${offset})
      list(APPEND result ${inner})
      continue()
    endif()
    _glint_json_string(name_json "${prefix}${member_name}")
    set(member_json "{\"name\": ${name_json}, \"type\": \"${member_type}\", \"offset\": ${offset}")
    string(JSON array_length ERROR_VARIABLE no_array GET "${member}" array 0)
    if(NOT no_array)
      string(APPEND member_json ", \"array\": ${array_length}")
    endif()
    string(APPEND member_json "}")
    list(APPEND result "${member_json}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# SPIRV-Cross reflection category -> the kind of descriptor an engine creates for it.
set(kind_ubos uniform_buffer)
set(kind_ssbos storage_buffer)
set(kind_images storage_image)
set(kind_separate_images sampled_image)
set(kind_separate_samplers sampler)
set(kind_textures combined_image_sampler)

set(bindings "")
set(constants "")
foreach(category ubos ssbos images separate_images separate_samplers textures)
  string(JSON count ERROR_VARIABLE missing LENGTH "${reflection}" "${category}")
  if(missing OR count EQUAL 0)
    continue()
  endif()
  math(EXPR last "${count} - 1")
  foreach(index RANGE ${last})
    string(JSON entry GET "${reflection}" "${category}" ${index})
    string(JSON name GET "${entry}" name)
    string(JSON set GET "${entry}" set)
    string(JSON slot GET "${entry}" binding)
    _glint_json_get(readonly "${entry}" readonly false)
    _glint_json_get(writeonly "${entry}" writeonly false)
    if(category MATCHES "^(ubos|separate_images|separate_samplers|textures)$")
      set(access read)
    elseif(readonly)
      set(access read)
    elseif(writeonly)
      set(access write)
    else()
      set(access read_write)
    endif()
    _glint_json_string(name_json "${name}")
    set(binding "{\"set\": ${set}, \"binding\": ${slot}, \"name\": ${name_json}, \"kind\": \"${kind_${category}}\", \"access\": \"${access}\"")
    if(category STREQUAL "images")
      string(JSON format GET "${entry}" format)
      string(APPEND binding ", \"format\": \"${format}\"")
    endif()
    if(category STREQUAL "ubos")
      string(JSON type_id GET "${entry}" type)
      string(JSON type GET "${reflection}" types "${type_id}")
      string(JSON block_size GET "${entry}" block_size)
      # A cbuffer wrapping one struct (the entry files' form) is described as that struct.
      string(JSON member_count LENGTH "${type}" members)
      string(JSON only_type GET "${type}" members 0 type)
      string(JSON only_is_struct ERROR_VARIABLE not_struct GET "${reflection}" types "${only_type}")
      if(member_count EQUAL 1 AND NOT not_struct)
        set(type_id "${only_type}")
      endif()
      string(JSON struct_name GET "${reflection}" types "${type_id}" name)
      string(REGEX REPLACE "^type\\.(ConstantBuffer\\.)?" "" struct_name "${struct_name}")
      _glint_flatten_members(members "${type_id}" "" 0)
      list(JOIN members ",\n        " members)
      _glint_json_string(struct_json "${struct_name}")
      list(APPEND constants "{\"binding\": ${slot}, \"set\": ${set}, \"struct\": ${struct_json}, \"size\": ${block_size},\n      \"members\": [\n        ${members}]}")
    endif()
    string(APPEND binding "}")
    # Sorted by (set, binding): a zero-padded key in front, removed after sorting.
    string(LENGTH "${set}" set_digits)
    string(LENGTH "${slot}" slot_digits)
    string(SUBSTRING "0000${set}" ${set_digits} 4 set_key)
    string(SUBSTRING "0000${slot}" ${slot_digits} 4 slot_key)
    list(APPEND bindings "${set_key}${slot_key}|${binding}")
  endforeach()
endforeach()
list(SORT bindings)
list(TRANSFORM bindings REPLACE "^[0-9]+\\|" "")
list(JOIN bindings ",\n    " bindings)
list(JOIN constants ",\n    " constants)

string(JSON shape_x GET "${reflection}" entryPoints 0 workgroup_size 0)
string(JSON shape_y GET "${reflection}" entryPoints 0 workgroup_size 1)
string(JSON shape_z GET "${reflection}" entryPoints 0 workgroup_size 2)

set(defines_json "")
foreach(define IN LISTS DEFINES)
  _glint_json_string(define_json "${define}")
  list(APPEND defines_json "${define_json}")
endforeach()
list(JOIN defines_json ", " defines_json)
_glint_json_string(name_json "${NAME}")
_glint_json_string(source_json "${SOURCE}")

file(WRITE "${JSON_OUT}" "{
  \"format\": \"glint-shader\",
  \"version\": 1,
  \"module\": ${name_json},
  \"source\": ${source_json},
  \"entry_point\": \"main\",
  \"defines\": [${defines_json}],
  \"compiler\": \"${COMPILER}\",
  \"thread_shape\": [${shape_x}, ${shape_y}, ${shape_z}],
  \"bindings\": [
    ${bindings}],
  \"constants\": [
    ${constants}]
}
")

# GLSL 450 for OpenGL: SPIRV-Cross combines each sampled image with its sampler; binding
# numbers are kept (GL has one binding space per resource type, so they do not collide).
execute_process(COMMAND "${SPIRV_CROSS}" "${SPIRV}" --version 450 --no-es --output "${GLSL_OUT}.tmp"
                ERROR_VARIABLE error RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NAME}: spirv-cross could not translate the module to GLSL 450: ${error}")
endif()
file(READ "${GLSL_OUT}.tmp" glsl)
file(REMOVE "${GLSL_OUT}.tmp")
list(JOIN DEFINES " " defines_text)
if(defines_text STREQUAL "")
  set(defines_text "none")
endif()
file(WRITE "${GLSL_OUT}" "// glint ${NAME}: GLSL 450 translation of ${SOURCE} (defines: ${defines_text}),
// made by SPIRV-Cross from the SPIR-V module and checked by glslang. Generated; do not edit.
${glsl}")
execute_process(COMMAND "${GLSLANG}" -S comp "${GLSL_OUT}"
                OUTPUT_VARIABLE log ERROR_VARIABLE log RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  file(REMOVE "${GLSL_OUT}")
  message(FATAL_ERROR "${NAME}: glslang rejects the GLSL 450 translation:\n${log}")
endif()
