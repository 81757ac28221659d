# Script mode: the hybrid effect end to end under the validation layer. The mirror corridor
# simulated with references (its manifest records the scene, which the hybrid's ray tracer
# rebuilds), replayed with the hybrid effect and with SSSR's reflections effect, both denoised:
# the hybrid's error against reference.reflection must be at most half of SSSR's on every frame.
# Then the bundled sample (a capture with no scene) refused in one line with exit 2.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")

run_glint(0 --validate simulate "${SCENES}/mirror_corridor.toml" --size 96x54 --frame-count 3 --spp 8
          --out "${OUT}/capture")
foreach(effect hybrid reflections)
  run_glint(0 --validate run "${OUT}/capture" --effects ${effect} --set denoise=true --out "${OUT}/${effect}")
  file(READ "${OUT}/${effect}/summary.json" json_${effect})
endforeach()
# A non-negative decimal number (as JSON writes the errors) in millionths, for integer math.
function(to_millionths value out)
  if(NOT value MATCHES "^([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "not a plain decimal: ${value}")
  endif()
  set(whole "${CMAKE_MATCH_1}")
  set(fraction "${CMAKE_MATCH_3}000000")
  string(SUBSTRING "${fraction}" 0 6 fraction)
  string(REGEX REPLACE "^0+([0-9])" "\\1" fraction "${fraction}")
  math(EXPR result "${whole} * 1000000 + ${fraction}")
  set(${out} ${result} PARENT_SCOPE)
endfunction()
foreach(frame 0 1 2)
  string(JSON hybrid GET "${json_hybrid}" frames ${frame} errors hybrid mean)
  string(JSON sssr GET "${json_reflections}" frames ${frame} errors reflections mean)
  to_millionths("${hybrid}" hybrid_m)
  to_millionths("${sssr}" sssr_m)
  math(EXPR twice "2 * ${hybrid_m}")
  message(STATUS "frame ${frame}: hybrid ${hybrid}, SSSR ${sssr}")
  if(twice GREATER sssr_m)
    message(FATAL_ERROR "frame ${frame}: the hybrid's error ${hybrid} is not at most half of SSSR's ${sssr}")
  endif()
endforeach()
if(NOT EXISTS "${OUT}/hybrid/frame_0002/hybrid_denoised.png")
  message(FATAL_ERROR "run wrote no hybrid_denoised.png")
endif()

run_glint(2 run "${SAMPLE}" --effects hybrid --out "${OUT}/refused")
string(STRIP "${run_err}" line)
if(NOT line MATCHES "hybrid" OR NOT line MATCHES "scene" OR line MATCHES "\n")
  message(FATAL_ERROR "expected one line naming the hybrid effect and the missing scene, got: ${run_err}")
endif()
