# Script mode: glint run, dump and check --geometry FILE under the validation layer. A corridor
# whose every object glTF holds exactly (tests/cli/scenes/geometry_corridor.toml) is simulated
# (its manifest records the scene) and written as glTF by glint_export_geometry. The hybrid
# effect replayed from the manifest's scene is dumped; then the capture with the manifest's
# scene taken out (a foreign capture, as far as geometry goes) is checked with --geometry
# against that dump with every hybrid pass compared exactly (check's defaults allow the float
# passes the rounding of another GPU; here both roads run on one device): the same triangles in
# the same order, materials and lights give the same BVH and the same shading, bit for bit. Then: --geometry wins over a manifest scene that cannot be loaded; the
# capture without a scene and without --geometry is refused in one line naming --geometry.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/run_glint.cmake")
set(exact)
foreach(pass intersect trace shade reproject prefilter resolve)
  list(APPEND exact --tolerance "hybrid/${pass}=0,0,0")
endforeach()

run_glint(0 --validate simulate "${SCENE}" --out "${OUT}/capture")
execute_process(COMMAND "${EXPORT}" "${SCENE}" "${OUT}/corridor.gltf" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "glint_export_geometry failed: ${status}")
endif()

# The manifest's road.
run_glint(0 dump "${OUT}/capture" --effects hybrid --pass all --out "${OUT}/manifest_dump")

# A copy without the manifest's scene, and one whose scene cannot be loaded.
file(READ "${OUT}/capture/manifest.json" manifest)
string(JSON scene ERROR_VARIABLE no_scene GET "${manifest}" scene)
if(no_scene)
  message(FATAL_ERROR "the simulated capture's manifest records no scene: ${no_scene}")
endif()
string(JSON stripped REMOVE "${manifest}" scene)
string(JSON broken SET "${manifest}" scene "\"${OUT}/no_such_scene.toml\"")
foreach(copy foreign broken)
  file(COPY "${OUT}/capture/" DESTINATION "${OUT}/${copy}")
endforeach()
file(WRITE "${OUT}/foreign/manifest.json" "${stripped}")
file(WRITE "${OUT}/broken/manifest.json" "${broken}")

# The file's road, against the manifest's: every hybrid image of the last frame, exactly.
run_glint(0 --validate check "${OUT}/foreign" --effects hybrid --geometry "${OUT}/corridor.gltf"
          --expected "${OUT}/manifest_dump" ${exact})
if(NOT run_out MATCHES "hybrid/shade +noisy +0 +0 +0.000 +0.000  ok")
  message(FATAL_ERROR "check did not compare the ray-traced radiance (hybrid/shade noisy) equal")
endif()
if(NOT run_out MATCHES "([0-9]+) image\\(s\\) compared, 0 differ")
  message(FATAL_ERROR "check did not compare every image equal")
endif()
message(STATUS "${CMAKE_MATCH_1} images equal on both roads")
# The comparison sees the file's materials: the lamp's emission at a quarter (its glTF
# emissive strength 4 made 1) changes the ray-traced radiance.
file(READ "${OUT}/corridor.gltf" gltf)
string(REPLACE "\"emissiveStrength\":4" "\"emissiveStrength\":1" dim "${gltf}")
if(dim STREQUAL gltf)
  message(FATAL_ERROR "corridor.gltf has no emissive strength 4 to change")
endif()
file(WRITE "${OUT}/dim.gltf" "${dim}")
run_glint(1 check "${OUT}/foreign" --effects hybrid --geometry "${OUT}/dim.gltf" --expected "${OUT}/manifest_dump"
          ${exact})
if(NOT run_out MATCHES "hybrid/shade +noisy [^\n]*FAIL")
  message(FATAL_ERROR "a dimmer lamp did not change the ray-traced radiance")
endif()

run_glint(0 --validate run "${OUT}/foreign" --effects hybrid --geometry "${OUT}/corridor.gltf" --out "${OUT}/run")
if(NOT EXISTS "${OUT}/run/frame_0001/hybrid_noisy.png")
  message(FATAL_ERROR "run --geometry wrote no hybrid_noisy.png")
endif()

# The file wins over the manifest's scene (which here cannot even be loaded).
run_glint(2 run "${OUT}/broken" --effects hybrid --out "${OUT}/broken_run")
run_glint(0 run "${OUT}/broken" --effects hybrid --geometry "${OUT}/corridor.gltf" --out "${OUT}/broken_run")

# No scene and no --geometry: one line that says what to give.
run_glint(2 run "${OUT}/foreign" --effects hybrid --out "${OUT}/refused")
string(STRIP "${run_err}" line)
if(NOT line MATCHES "hybrid" OR NOT line MATCHES "--geometry FILE" OR line MATCHES "\n")
  message(FATAL_ERROR "expected one line naming the hybrid effect and --geometry, got: ${run_err}")
endif()
