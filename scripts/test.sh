#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds the debug preset (AddressSanitizer
# and UndefinedBehaviorSanitizer) and runs every test under the Khronos validation layer on
# the selected Vulkan device (lavapipe where there is no GPU). Extra arguments go to ctest,
# e.g. scripts/test.sh -L unit.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" debug
cd "$root"
jobs=$(nproc 2>/dev/null || echo 2)
ctest --preset debug -j "$jobs" "$@"
