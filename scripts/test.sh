#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds the debug preset (AddressSanitizer
# and UndefinedBehaviorSanitizer) and runs every test under the Khronos validation layer on
# the selected Vulkan device (lavapipe where there is no GPU), and the libFuzzer targets' smoke
# run (their own clang build, the fuzz preset). Extra arguments go to ctest,
# e.g. scripts/test.sh -L unit.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" debug
# The fuzz targets' smoke run is one of the tests (label fuzz); they have a build of their own.
"$root/scripts/setup.sh" fuzz
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
ctest --preset debug -j "$jobs" "$@"
