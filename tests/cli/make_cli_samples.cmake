# Script mode: writes the sample sequence with glint_make_sample, Blender-style renders with
# glint_make_blender_sample, then malformed files.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
execute_process(COMMAND "${MAKE_SAMPLE}" "${DIR}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glint_make_sample failed: ${status}")
endif()
execute_process(COMMAND "${MAKE_BLENDER}" "${DIR}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glint_make_blender_sample failed: ${status}")
endif()
# A truncated copy: the header survives, most of the pixel data does not.
file(SIZE "${DIR}/sample/frame_0000.exr" size)
math(EXPR keep "${size} / 2")
execute_process(COMMAND head -c ${keep} "${DIR}/sample/frame_0000.exr" OUTPUT_FILE "${DIR}/truncated.exr"
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "could not write truncated.exr")
endif()
file(WRITE "${DIR}/not_exr.exr" "this is a text file, not an OpenEXR image\n")
# The sample sequence with a frame rate beyond the range of a double.
file(COPY "${DIR}/sample/" DESTINATION "${DIR}/overflow_manifest")
file(READ "${DIR}/sample/manifest.json" manifest)
string(REGEX REPLACE "\"frameRate\": [0-9.]+" "\"frameRate\": 1e999" manifest "${manifest}")
if(NOT manifest MATCHES "1e999")
  message(FATAL_ERROR "could not write overflow_manifest/manifest.json")
endif()
file(WRITE "${DIR}/overflow_manifest/manifest.json" "${manifest}")
# The sample sequence with its last frame truncated (header intact): replays must fail on it
# before they write anything for the frames before it.
file(COPY "${DIR}/sample/" DESTINATION "${DIR}/truncated_last_frame")
execute_process(COMMAND head -c ${keep} "${DIR}/sample/frame_0001.exr"
                OUTPUT_FILE "${DIR}/truncated_last_frame/frame_0001.exr" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "could not write truncated_last_frame/frame_0001.exr")
endif()
