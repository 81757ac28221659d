// The translation unit that builds the test suites' precompiled Catch2 header (tests/CMakeLists.txt).
