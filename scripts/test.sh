#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds the debug preset (AddressSanitizer
# and UndefinedBehaviorSanitizer) and runs every test under the Khronos validation layer on
# the selected Vulkan device (lavapipe where there is no GPU), and the libFuzzer targets' smoke
# run (their own clang build, the fuzz preset). Extra arguments go to ctest,
# e.g. scripts/test.sh -L unit.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# DXC (GLINT_DXC, else dxc on PATH as the Vulkan SDK installs it): glint stays built by glslang,
# and the suite also compiles every module and header check with DXC to SPIR-V and DXIL under -WX
# and runs the GPU suites (label gpu, not slow) again on DXC's SPIR-V (cmake/GlintDxcTests.cmake).
dxc=${GLINT_DXC:-$(command -v dxc || true)}
if [ -n "$dxc" ] && "$dxc" --version >/dev/null 2>&1; then
  dxc=$(cd "$(dirname "$dxc")" && pwd)/$(basename "$dxc")
  echo "test: DXC tests with $dxc ($("$dxc" --version 2>&1 | head -1))"
  export GLINT_CONFIGURE_ARGS="-DGLINT_DXC_TESTS=$dxc"
elif [ "${CI:-}" = true ] || [ -n "${GLINT_FORBID_SKIPS:-}" ]; then
  echo "test: no DXC that runs (GLINT_DXC='${GLINT_DXC:-}', none on PATH); CI and GLINT_FORBID_SKIPS require one" >&2
  exit 1
else
  echo "test: no DXC (set GLINT_DXC or put dxc on PATH): testing glslang's SPIR-V only"
  export GLINT_CONFIGURE_ARGS="-DGLINT_DXC_TESTS="
fi
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
