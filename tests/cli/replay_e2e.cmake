# Script mode: one end-to-end replay case under the validation layer (any error exits 1).
#   reflections: the glossy room with references through run with the denoiser; the denoised
#                error against reference.reflection must be below the noisy input's and under
#                a bound, with no non-finite pixel
#   shadows:     the courtyard through run; the denoised error over receivers against
#                reference.shadow must be below the noisy input's and under a bound, the
#                penumbra's under a bound, with no non-finite pixel
#   roundtrip:   dump a frame, check it against itself (exit 0), then against a dump made with
#                a different traversal budget (exit 1, the intersection differs), then report
file(REMOVE_RECURSE "${OUT}")
function(glint_step)
  execute_process(COMMAND "${GLINT}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "glint ${ARGN}: exit ${status}\n${out}${err}")
  set(step_status "${status}" PARENT_SCOPE)
  set(step_out "${out}" PARENT_SCOPE)
endfunction()
function(glint_expect code)
  glint_step(${ARGN})
  if(NOT "${step_status}" STREQUAL "${code}")
    message(FATAL_ERROR "glint ${ARGN}: expected exit ${code}, got ${step_status}")
  endif()
  set(step_out "${step_out}" PARENT_SCOPE)
endfunction()
# summary.json's error.<effect>.<key> as a number.
function(summary_error effect key variable)
  file(READ "${OUT}/run/summary.json" json)
  string(JSON value GET "${json}" error ${effect} ${key})
  set(${variable} "${value}" PARENT_SCOPE)
endfunction()
function(require_less name value bound)
  if(NOT value LESS bound)
    message(FATAL_ERROR "${name} = ${value}, not below ${bound}")
  endif()
  message(STATUS "${name} = ${value} (bound ${bound})")
endfunction()

if(CASE STREQUAL "reflections")
  glint_expect(0 --validate simulate "${SCENES}/glossy_room.toml" --size 96x54 --frame-count 6 --spp 16 --out "${OUT}/capture")
  glint_expect(0 --validate run "${OUT}/capture" --set denoise=true --set composite=true --out "${OUT}/run")
  summary_error(reflections last denoised)
  summary_error(reflections noisyLast noisy)
  # Measured on lavapipe 2026-11-22 and again 2026-12-02: denoised 0.450, noisy input 0.864
  # (mean relative error over glossy pixels). The camera moves every frame in this scene.
  require_less("denoised error" "${denoised}" 0.55)
  require_less("denoised error relative to the noisy input" "${denoised}" "${noisy}")
  foreach(image noisy denoised composite reference error)
    if(NOT EXISTS "${OUT}/run/frame_0005/reflections_${image}.png")
      message(FATAL_ERROR "run wrote no reflections_${image}.png")
    endif()
  endforeach()
elseif(CASE STREQUAL "shadows")
  glint_expect(0 --validate simulate "${SCENES}/courtyard_penumbra.toml" --size 96x54 --frame-count 6 --spp 16 --out "${OUT}/capture")
  glint_expect(0 --validate run "${OUT}/capture" --out "${OUT}/run")
  summary_error(shadows last denoised)
  summary_error(shadows noisyLast noisy)
  file(READ "${OUT}/run/summary.json" json)
  string(JSON frames LENGTH "${json}" frames)
  math(EXPR lastFrame "${frames} - 1")
  string(JSON penumbra GET "${json}" frames ${lastFrame} errors shadows penumbra)
  string(JSON nonFinite GET "${json}" frames ${lastFrame} errors shadows nonFinite)
  # Measured on lavapipe 2026-12-02: mean |error| over receivers 0.0038 against the noisy
  # input's 0.0045 (most receivers are fully lit or shadowed, where both are exact), penumbra
  # 0.147 (the penumbra gap of issue 7: the plain average of the input is lower; see
  # docs/shadow_denoiser.md). The absolute bounds only catch a broken run.
  require_less("denoised shadow error over receivers relative to the noisy input" "${denoised}" "${noisy}")
  require_less("denoised shadow error over receivers" "${denoised}" 0.015)
  require_less("denoised shadow error over the penumbra" "${penumbra}" 0.2)
  if(NOT nonFinite EQUAL 0)
    message(FATAL_ERROR "non-finite shadow pixels: ${nonFinite}")
  endif()
elseif(CASE STREQUAL "roundtrip")
  glint_expect(0 --validate simulate "${SCENES}/glossy_room.toml" --size 64x36 --frame-count 2 --spp 4 --out "${OUT}/capture")
  glint_expect(0 --validate dump "${OUT}/capture" --set denoise=true --out "${OUT}/dump")
  foreach(file reflections/intersect/noisy.exr reflections/classify/ray_list.png reflections/depth_pyramid/pyramid_mip1.exr
               reflections/resolve/variance.exr reflections/input/input_depth.exr
               reflections/input/input_normals.exr reflections/input/input_motion.exr index.json)
    if(NOT EXISTS "${OUT}/dump/${file}")
      message(FATAL_ERROR "dump wrote no ${file}")
    endif()
  endforeach()
  glint_expect(0 --validate check "${OUT}/capture" --set denoise=true --expected "${OUT}/dump")
  if(NOT step_out MATCHES "reflections/intersect +noisy.*ok.*0 differ")
    message(FATAL_ERROR "check against its own dump did not pass every image")
  endif()
  glint_expect(0 dump "${OUT}/capture" --set denoise=true --set maxTraversalIterations=2 --pass intersect
               --out "${OUT}/dump_short")
  glint_expect(1 check "${OUT}/capture" --set denoise=true --expected "${OUT}/dump_short" --pass intersect)
  if(NOT step_out MATCHES "reflections/intersect +noisy.*FAIL")
    message(FATAL_ERROR "check did not flag the intersection made with another traversal budget")
  endif()
  glint_expect(0 run "${OUT}/capture" --out "${OUT}/run")
  glint_expect(0 report "${OUT}/run" --out "${OUT}/report.html")
  file(READ "${OUT}/report.html" html)
  if(NOT html MATCHES "data:image/png;base64," OR html MATCHES "https?://")
    message(FATAL_ERROR "report.html does not embed its images or links outside")
  endif()
else()
  message(FATAL_ERROR "unknown CASE ${CASE}")
endif()
