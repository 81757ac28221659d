# The installed package as a studio would use it: cmake --install into a fresh prefix, then
# tests/consumer configured, built and run against that prefix alone (consumer_test.cmake).
add_test(NAME "consumer: the installed package builds engine entry files and runs a plan"
  COMMAND "${CMAKE_COMMAND}" "-DBUILD_DIR=${PROJECT_BINARY_DIR}" "-DSOURCE=${CMAKE_CURRENT_SOURCE_DIR}/consumer"
          "-DWORK=${PROJECT_BINARY_DIR}/test-output/consumer" "-DCXX=${CMAKE_CXX_COMPILER}"
          -P "${CMAKE_CURRENT_SOURCE_DIR}/consumer/consumer_test.cmake")
set_tests_properties("consumer: the installed package builds engine entry files and runs a plan"
  PROPERTIES LABELS gpu TIMEOUT 600)
