# Script mode: Blender-style renders (0001.exr, 0002.exr) through the shipped map under the
# validation layer. Outputs are named by the frames' own numbers (frame_0001, frame_0002),
# glint's own captures keep theirs (frame_0000, frame_0001), --frames stays a position, and
# report finds the last frame's images.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")
function(require_files)
  foreach(file IN LISTS ARGN)
    if(NOT EXISTS "${OUT}/${file}")
      message(FATAL_ERROR "missing ${OUT}/${file}")
    endif()
  endforeach()
endfunction()
function(require_no_files)
  foreach(file IN LISTS ARGN)
    if(EXISTS "${OUT}/${file}")
      message(FATAL_ERROR "unexpected ${OUT}/${file}")
    endif()
  endforeach()
endfunction()

# Without the Diffuse Color pass and without world.exr: replays, composite off.
run_glint(0 --validate run "${SAMPLES}/blender" --map "${MAP}" --out "${OUT}/plain")
require_files(plain/frame_0001/reflections_input.exr plain/frame_0002/reflections_noisy.png)
require_no_files(plain/frame_0000)
file(READ "${OUT}/plain/summary.json" json)
string(JSON folder GET "${json}" frames 0 folder)
string(JSON number GET "${json}" frames 1 number)
string(JSON index GET "${json}" frames 1 frame)
if(NOT folder STREQUAL "frame_0001" OR NOT number EQUAL 2 OR NOT index EQUAL 1)
  message(FATAL_ERROR "summary.json: frames[0].folder ${folder}, frames[1].number ${number}, frames[1].frame ${index}")
endif()

# With the pass and the world panorama: composite runs; --frames 1 is the second frame, 0002.exr.
run_glint(0 --validate run "${SAMPLES}/blender_full" --map "${MAP}" --set composite=true --set denoise=true
             --frames 1 --out "${OUT}/full")
require_files(full/frame_0002/reflections_composite.png full/frame_0002/reflections_denoised.exr)
require_no_files(full/frame_0001)
run_glint(0 report "${OUT}/full" --out "${OUT}/report.html")
file(READ "${OUT}/report.html" html)
if(NOT html MATCHES "Images of the last frame [(]frame_0002[)]" OR NOT html MATCHES "data:image/png;base64,")
  message(FATAL_ERROR "report.html does not show frame_0002's images")
endif()

# glint's own capture (frame_0000.exr, frame_0001.exr): unchanged names.
run_glint(0 run "${SAMPLES}/sample" --out "${OUT}/glint")
require_files(glint/frame_0000/reflections_input.exr glint/frame_0001/reflections_input.exr)
