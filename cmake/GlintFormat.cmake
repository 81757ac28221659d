# Script mode: runs clang-format over the tracked C++ sources (git ls-files at build time, so
# the list is never stale and no glob runs at configure time).
# hlsl/ is left out: its headers are compiled by HLSL compilers too and keep their own layout.
if(NOT CLANG_FORMAT OR NOT GIT)
  message(FATAL_ERROR "the format check needs clang-format and git, and configure found "
                      "clang-format '${CLANG_FORMAT}', git '${GIT}': install them (scripts/setup.sh does) "
                      "and configure again")
endif()
execute_process(COMMAND "${GIT}" ls-files -- "host/*.cpp" "host/*.h" "harness/*.cpp" "harness/*.h" ":!harness/shaders" "tests/*.cpp" "tests/*.h"
                WORKING_DIRECTORY "${ROOT}" OUTPUT_VARIABLE files OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "git ls-files failed in ${ROOT}")
endif()
string(REPLACE "\n" ";" files "${files}")
if(MODE STREQUAL "format")
  set(args -i)
else()
  set(args --dry-run -Werror)
endif()
execute_process(COMMAND "${CLANG_FORMAT}" ${args} ${files} WORKING_DIRECTORY "${ROOT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "clang-format: sources are not formatted; build the glint_format target")
endif()
