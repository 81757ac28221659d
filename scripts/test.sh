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
log=$(mktemp)
trap 'rm -f "$log"' EXIT
started=$(date +%s)
status=0
ctest --preset debug -j "$jobs" "$@" 2>&1 | tee "$log" || status=$?
# The wall time and the 15 slowest tests (a test over 120 s is a defect to shrink or split:
# CONTRIBUTING.md, "Test time").
echo "ctest wall time: $(( $(date +%s) - started )) s"
echo "slowest tests:"
grep -E '^ *[0-9]+/[0-9]+ Test +#[0-9]+: ' "$log" |
    awk '{ time = $(NF - 1); sub(/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: /, ""); sub(/ \.\.\.+.*$/, ""); printf "%8.1f s  %s\n", time, $0 }' |
    sort -rn | awk 'NR <= 15' || true
exit "$status"
