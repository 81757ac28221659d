# project()'s version and hlsl/glint/common/glint_version.h's macros are one number written
# twice (the header lives in the source tree so that engines compiling straight from hlsl/ have
# it too): configuring stops when they differ.
set(_glint_version_header "${PROJECT_SOURCE_DIR}/hlsl/glint/common/glint_version.h")
set(_glint_header_version "")
foreach(_glint_part MAJOR MINOR PATCH)
  file(STRINGS "${_glint_version_header}" _glint_line REGEX "^#define GLINT_VERSION_${_glint_part} [0-9]+$")
  if(NOT _glint_line MATCHES "([0-9]+)$")
    message(FATAL_ERROR "glint: ${_glint_version_header} has no '#define GLINT_VERSION_${_glint_part} <number>' line")
  endif()
  list(APPEND _glint_header_version "${CMAKE_MATCH_1}")
endforeach()
list(JOIN _glint_header_version "." _glint_header_version)
if(NOT _glint_header_version VERSION_EQUAL PROJECT_VERSION)
  message(FATAL_ERROR "glint: project() says version ${PROJECT_VERSION} but ${_glint_version_header} says "
                      "${_glint_header_version}; change both (and CHANGELOG.md)")
endif()
