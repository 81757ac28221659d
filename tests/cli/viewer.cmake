# glint view under Xvfb on the selected device, every run under the validation layer:
#   - --screenshot FILE --after 4 writes the composite of frame 4, equal within one 8-bit code
#     to glint run's composite of that frame;
#   - a script takes screenshots of two views of one frame (each equal to glint run's preview
#     of that image), changes a setting that fixes nothing (the next frame differs from run's)
#     and one that needs a new session (the next frame equals run's with that setting);
#   - without a display: one line and exit 2; a script line it cannot run: one line naming the
#     line and exit 2.
# Needs GLINT, COMPARE (glint_compare_png), SCENES, OUT.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  if("$ENV{CI}" STREQUAL "true" OR "$ENV{GLINT_FORBID_SKIPS}" STREQUAL "1")
    message(FATAL_ERROR "xvfb-run is missing (scripts/setup.sh installs xvfb)")
  endif()
  message("GLINT_SKIP: xvfb-run is missing (scripts/setup.sh installs xvfb)")
  return()
endif()
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")
function(compare mode a b)
  execute_process(COMMAND "${COMPARE}" ${mode} "${a}" "${b}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message(STATUS "compare ${mode} ${a} ${b} ${ARGN}: ${out}${err}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${a} and ${b}: not '${mode}' (${ARGN}): ${out}${err}")
  endif()
endfunction()
# One X server per command (xvfb-run -a picks a free display).
set(X "${XVFB_RUN}" -a -s "-screen 0 1280x1024x24")
function(run_view expected)
  execute_process(COMMAND ${X} "${GLINT}" --validate view ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  message(STATUS "glint view ${ARGN}: exit ${status}\n${out}${err}")
  if(NOT "${status}" STREQUAL "${expected}")
    message(FATAL_ERROR "glint view ${ARGN}: expected exit ${expected}, got ${status}")
  endif()
  set(view_err "${err}" PARENT_SCOPE)
endfunction()

set(capture "${OUT}/capture")
run_glint(0 simulate "${SCENES}/glossy_room.toml" --size 96x54 --frame-count 6 --spp 16 --out "${capture}")
set(denoised --set denoise=true --set composite=true)
run_glint(0 --validate run "${capture}" ${denoised} --out "${OUT}/run")
run_glint(0 --validate run "${capture}" --set composite=true --out "${OUT}/run_noisy")

# --screenshot --after
run_view(0 "${capture}" ${denoised} --screenshot "${OUT}/after4.png" --after 4)
compare(same "${OUT}/after4.png" "${OUT}/run/frame_0004/reflections_composite.png" 1)

# A script: a view change, a live setting change, a setting that needs a new session.
file(WRITE "${OUT}/script.txt" "# the composite, then the noisy reflection of the same frame
step 2
screenshot ${OUT}/composite2.png
view reflections/noisy
screenshot ${OUT}/noisy2.png
view reflections/composite
# rays that stop after one step find almost nothing
set maxTraversalIterations=1
step
screenshot ${OUT}/short3.png
set maxTraversalIterations=128
# the denoiser off: the effect's resources change, the session is made again
set denoise=false
step
screenshot ${OUT}/undenoised4.png
quit
")
run_view(0 "${capture}" ${denoised} --script "${OUT}/script.txt")
compare(same "${OUT}/composite2.png" "${OUT}/run/frame_0002/reflections_composite.png" 1)
compare(same "${OUT}/noisy2.png" "${OUT}/run/frame_0002/reflections_noisy.png" 1)
compare(differ "${OUT}/noisy2.png" "${OUT}/composite2.png" 1 100)
compare(differ "${OUT}/short3.png" "${OUT}/run/frame_0003/reflections_composite.png" 1 100)
compare(same "${OUT}/undenoised4.png" "${OUT}/run_noisy/frame_0004/reflections_composite.png" 1)

# No display.
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY "${GLINT}" view "${capture}"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err STREQUAL "glint view: no display; set DISPLAY or use glint run\n" OR NOT out STREQUAL "")
  message(FATAL_ERROR "without a display: exit ${status}, stdout '${out}', stderr '${err}'")
endif()

# A script line naming an image the replay does not have.
file(WRITE "${OUT}/bad.txt" "step\nview reflections/nothing\n")
run_view(2 "${capture}" --script "${OUT}/bad.txt")
string(REGEX MATCHALL "\n" lines "${view_err}")
list(LENGTH lines count)
if(NOT count EQUAL 1 OR NOT view_err MATCHES "^glint: [^\n]*bad.txt:2: no image 'reflections/nothing' in this replay \\(")
  message(FATAL_ERROR "a bad script line: expected one line naming bad.txt:2, got '${view_err}'")
endif()
