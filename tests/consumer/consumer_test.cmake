# Script mode (cmake -P): installs glint from BUILD_DIR into a fresh prefix under WORK, then
# configures, builds and runs the consumer project (SOURCE) against that prefix only, so that
# nothing of the source tree is on its include paths. Then checks which versions find_package
# accepts (the installed glint_version.h's MAJOR.MINOR and nothing newer or of another minor),
# and that a package whose vulkan component is missing fails find_package with a message
# naming the component.
#   -DBUILD_DIR=... -DSOURCE=... -DWORK=... -DCXX=...
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "failed (${result}): ${ARGN}\n${out}\n${err}")
  endif()
  message("${out}")
endfunction()

file(REMOVE_RECURSE "${WORK}")
set(prefix "${WORK}/prefix")
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
run("${CMAKE_COMMAND}" -S "${SOURCE}" -B "${WORK}/build" -G Ninja "-DCMAKE_PREFIX_PATH=${prefix}"
    "-DCMAKE_CXX_COMPILER=${CXX}")
run("${CMAKE_COMMAND}" --build "${WORK}/build")
run("${WORK}/build/glint_consumer")

# find_package(glint <version> CONFIG) against the installed headers' version M.m.p: M.m and
# M.m.p are accepted; M.m.(p+1), M.(m+1), (M+1).0 and M.(m-1) are not (a 0.x minor release may
# break the callback API: docs/integration.md, "Versions").
set(header "${prefix}/include/glint-hlsl/glint/common/glint_version.h")
foreach(part MAJOR MINOR PATCH)
  file(STRINGS "${header}" line REGEX "^#define GLINT_VERSION_${part} [0-9]+$")
  string(REGEX MATCH "[0-9]+$" v_${part} "${line}")
  if(v_${part} STREQUAL "")
    message(FATAL_ERROR "${header}: no GLINT_VERSION_${part}")
  endif()
endforeach()
math(EXPR next_patch "${v_PATCH} + 1")
math(EXPR next_minor "${v_MINOR} + 1")
math(EXPR next_major "${v_MAJOR} + 1")
math(EXPR previous_minor "${v_MINOR} - 1")
set(accepted "${v_MAJOR}.${v_MINOR}" "${v_MAJOR}.${v_MINOR}.${v_PATCH}")
set(rejected "${v_MAJOR}.${v_MINOR}.${next_patch}" "${v_MAJOR}.${next_minor}" "${next_major}.0")
if(v_MINOR GREATER 0)
  list(APPEND rejected "${v_MAJOR}.${previous_minor}")
endif()
foreach(version IN LISTS accepted rejected)
  string(REPLACE "." "_" name "version_${version}")
  file(WRITE "${WORK}/${name}/CMakeLists.txt"
       "cmake_minimum_required(VERSION 3.25)\nproject(${name} LANGUAGES NONE)\n"
       "find_package(glint ${version} CONFIG REQUIRED COMPONENTS hlsl)\n"
       "message(STATUS \"glint \${glint_VERSION}\")\n")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${WORK}/${name}" -B "${WORK}/${name}/build" -G Ninja
                          "-DCMAKE_PREFIX_PATH=${prefix}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  list(FIND accepted "${version}" accepted_index)
  if(accepted_index GREATER -1)
    if(NOT result EQUAL 0 OR NOT out MATCHES "glint ${v_MAJOR}\\.${v_MINOR}\\.${v_PATCH}")
      message(FATAL_ERROR "find_package(glint ${version}) failed against ${v_MAJOR}.${v_MINOR}.${v_PATCH}:\n${out}\n${err}")
    endif()
  elseif(result EQUAL 0)
    message(FATAL_ERROR "find_package(glint ${version}) accepted glint ${v_MAJOR}.${v_MINOR}.${v_PATCH}")
  elseif(NOT "${out}${err}" MATCHES "version")
    message(FATAL_ERROR "find_package(glint ${version}) failed without naming the version:\n${out}\n${err}")
  endif()
endforeach()

# The same package without its Vulkan backend, as GLINT_BUILD_VULKAN=OFF installs it.
file(REMOVE "${prefix}/lib/cmake/glint/glint-vulkan-targets.cmake")
file(GLOB leftovers "${prefix}/lib/cmake/glint/glint-vulkan-targets-*.cmake")
if(leftovers)
  file(REMOVE ${leftovers})
endif()
file(WRITE "${WORK}/missing/CMakeLists.txt"
     "cmake_minimum_required(VERSION 3.25)\nproject(missing LANGUAGES NONE)\n"
     "find_package(glint CONFIG REQUIRED COMPONENTS core)\n"
     "find_package(glint CONFIG REQUIRED COMPONENTS vulkan)\n")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${WORK}/missing" -B "${WORK}/missing/build" -G Ninja
                        "-DCMAKE_PREFIX_PATH=${prefix}"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(result EQUAL 0)
  message(FATAL_ERROR "find_package(glint COMPONENTS vulkan) succeeded without the vulkan component")
endif()
if(NOT "${out}${err}" MATCHES "component 'vulkan' was not built")
  message(FATAL_ERROR "find_package did not name the missing component:\n${out}\n${err}")
endif()
