# Script mode: `glint --validate simulate SCENE` at a tiny size, then `glint info` on what it
# wrote. Fails on any non-zero exit (validation errors included), on a warning, or when info
# does not list the frames.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${GLINT}" --validate simulate "${SCENE}" --size 32x18 --frame-count 2 --spp 2 --out "${OUT}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "simulate: exit ${status}\n${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glint simulate ${SCENE} exited ${status}")
endif()
# A bundled scene has no surface pixels at the background depth (docs/scenes.md).
if(err MATCHES "warning")
  message(FATAL_ERROR "glint simulate ${SCENE} warned: ${err}")
endif()
execute_process(COMMAND "${GLINT}" info "${OUT}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "info: exit ${status}\n${out}${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glint info on the simulated sequence exited ${status}")
endif()
string(REPLACE "\n" " " flat "${out}")
if(NOT flat MATCHES "frame_0000.exr.*depth.*motion")
  message(FATAL_ERROR "glint info does not describe the simulated frames")
endif()
