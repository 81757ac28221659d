# libFuzzer settings for the targets under tests/fuzz (GLINT_FUZZ=ON, `cmake --preset fuzz`,
# scripts/fuzz.sh, docs/robustness.md). clang only: libFuzzer comes with Debian's clang
# (package libclang-rt-14-dev on bookworm).
#
# Third-party code is fuzzed as glint ships it: OpenEXR, assimp and toml++ are Debian's
# shared libraries (not instrumented; their allocations still count against libFuzzer's
# malloc and RSS limits), nlohmann::json is header-only and instrumented with glint's code.
if(NOT GLINT_FUZZ)
  return()
endif()
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "glint: GLINT_FUZZ needs clang with libFuzzer (cmake --preset fuzz; scripts/fuzz.sh installs it)")
endif()
if(NOT GLINT_BUILD_HARNESS)
  message(FATAL_ERROR "glint: GLINT_FUZZ fuzzes the harness's readers; it needs GLINT_BUILD_HARNESS=ON")
endif()

# Libraries the fuzzers reach get coverage instrumentation and the sanitizers; the fuzz
# targets themselves also link libFuzzer's main.
set(GLINT_FUZZ_SANITIZERS address,undefined)
set(GLINT_FUZZ_COMPILE_OPTIONS -fsanitize=fuzzer-no-link,${GLINT_FUZZ_SANITIZERS}
                               -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g)

#   glint_fuzz_instrument(<library>...)
function(glint_fuzz_instrument)
  foreach(target IN LISTS ARGN)
    target_compile_options(${target} PRIVATE ${GLINT_FUZZ_COMPILE_OPTIONS})
  endforeach()
endfunction()

#   glint_add_fuzzer(NAME <name> SOURCES <file>... LIBS <target>...)
# Builds glint_fuzz_<name>; scripts/fuzz.sh runs it on tests/fuzz/corpus/<name>.
function(glint_add_fuzzer)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  set(exe glint_fuzz_${ARG_NAME})
  add_executable(${exe} ${ARG_SOURCES})
  target_link_libraries(${exe} PRIVATE ${ARG_LIBS})
  glint_target_defaults(${exe})
  target_compile_options(${exe} PRIVATE ${GLINT_FUZZ_COMPILE_OPTIONS})
  target_link_options(${exe} PRIVATE -fsanitize=fuzzer,${GLINT_FUZZ_SANITIZERS})
  add_dependencies(glint_fuzz ${exe})
endfunction()
