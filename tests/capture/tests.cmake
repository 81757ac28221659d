# Capture format v1 (harness/capture): one file per behaviour, all CPU-only.
glint_add_test_suite(NAME capture LABELS unit
  SOURCES
    capture/blender_capture.cpp
    capture/bounded_memory_test.cpp
    capture/capture_test_support.cpp
    capture/channel_map_test.cpp
    capture/describe_test.cpp
    capture/environment_test.cpp
    capture/foreign_capture_test.cpp
    capture/malformed_file_test.cpp
    capture/malformed_header_test.cpp
    capture/malformed_layers_test.cpp
    capture/mat4_test.cpp
    capture/motion_convention_test.cpp
    capture/non_finite_test.cpp
    capture/round_trip_test.cpp
    capture/sample_frame_test.cpp
    capture/sequence_test.cpp
    capture/standard_attributes_test.cpp
  LIBS glint_capture)
