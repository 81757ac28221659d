# Script mode: docs/replay.md's recipe "From a camera JSON you already have", taken from the
# page itself, turns the plain camera JSON of a Blender-style render (view, OpenGL projection,
# near, far per frame; glint_make_blender_sample's blender_plain) into camera.json, and the
# render then reads and replays through the shipped map.
#   -DGLINT=... -DPYTHON=... -DDOC=docs/replay.md -DSAMPLE=<blender_plain> -DMAP=... -DOUT=...
file(REMOVE_RECURSE "${OUT}")
file(COPY "${SAMPLE}/" DESTINATION "${OUT}/capture")
file(READ "${DOC}" doc)
string(FIND "${doc}" "```python\n# plain camera JSON -> glint's camera.json" begin)
if(begin LESS 0)
  message(FATAL_ERROR "${DOC}: no recipe block starting '# plain camera JSON -> glint's camera.json'")
endif()
string(SUBSTRING "${doc}" ${begin} -1 rest)
string(LENGTH "```python\n" fence)
string(SUBSTRING "${rest}" ${fence} -1 rest)
string(FIND "${rest}" "```" end)
string(SUBSTRING "${rest}" 0 ${end} recipe)
file(WRITE "${OUT}/recipe.py" "${recipe}")
execute_process(COMMAND "${PYTHON}" "${OUT}/recipe.py" plain_camera.json WORKING_DIRECTORY "${OUT}/capture"
                RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT EXISTS "${OUT}/capture/camera.json")
  message(FATAL_ERROR "the recipe failed (${status}): ${err}")
endif()
execute_process(COMMAND "${GLINT}" run "${OUT}/capture" --map "${MAP}" --out "${OUT}/run"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "glint run: exit ${status}\n${out}${err}")
if(NOT status EQUAL 0 OR NOT EXISTS "${OUT}/run/frame_0002/reflections_noisy.exr")
  message(FATAL_ERROR "the capture with the recipe's camera.json did not replay")
endif()
