# The replay library's pieces that need no device.
glint_add_test_suite(NAME replay_error LABELS unit SOURCES replay/reference_error_test.cpp replay/moving_edge_error_test.cpp LIBS glint_replay)
