#!/usr/bin/env bash
# The main job: installs what is missing, builds the release preset, then
#   - lists the Vulkan devices,
#   - describes the bundled sample capture,
#   - simulates every bundled scene (harness/scenes) into a capture sequence under out/scenes,
#   - measures the depth pyramid at 1920x1080 and SSSR on the glossy room at 640x360 on the
#     selected device (per-pass times, traced fraction, how the rays ended),
# and writes everything to out/report.md. GLINT_OUT moves out/, GLINT_DEVICE picks the device.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" release glint glint_make_sample
cd "$root"
bin=build/release/harness
glint="$bin/cli/glint"
out=${GLINT_OUT:-out}
mkdir -p "$out/scenes"
"$bin/capture/glint_make_sample" "$out"
{
  echo "# glint demo report"
  echo
  echo "## Devices"
  echo '```'
  "$glint" devices
  echo '```'
  echo
  echo "## Sample capture"
  echo '```'
  "$glint" info "$out/sample"
  echo '```'
  echo
  echo "## Bundled scenes (glint simulate, GPU time per pass)"
  for scene in harness/scenes/*.toml; do
    name=$(basename "$scene" .toml)
    echo
    echo "### $name"
    echo '```'
    "$glint" simulate "$scene" --out "$out/scenes/$name"
    echo '```'
  done
  echo
  echo "## Depth pyramid, 1920x1080 (glint bench)"
  echo '```'
  "$glint" bench depth_pyramid --size 1920x1080 --runs 20
  echo '```'
  echo
  echo "## Stochastic screen-space reflections, glossy room 640x360 (glint bench sssr)"
  echo '```'
  "$glint" bench sssr --size 640x360 --runs 10 --set debugOutput=true
  echo '```'
} | tee "$out/report.md"
echo "demo: wrote $out/report.md and the captures under $out/scenes"
