# Script mode (cmake -P): installs glint from BUILD_DIR into a fresh prefix under WORK, then
# configures, builds and runs the consumer project (SOURCE) against that prefix only, so that
# nothing of the source tree is on its include paths. Then checks that a package whose vulkan
# component is missing fails find_package with a message naming the component.
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
