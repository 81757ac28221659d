# Scene simulator (harness/scene, harness/shaders): the CPU parts (scene files, BVH) as unit
# tests, the ray caster on the device (gpu) against CPU ray casting and by its outputs.
glint_add_test_suite(NAME scene_unit LABELS unit
  SOURCES
    scene/bvh_test.cpp
    scene/scene_file_test.cpp
    scene/geometry_file_test.cpp
    scene/scene_gltf_export.cpp
  LIBS glint_scene)

glint_add_test_suite(NAME scene LABELS gpu HARNESS_SHADERS_ONLY
  SOURCES
    scene/scene_test_scenes.cpp
    scene/gbuffer_test.cpp
    scene/effects_test.cpp
    scene/convergence_test.cpp
    scene/environment_sampling_test.cpp
  LIBS glint_scene glint_gpu_test_support)
