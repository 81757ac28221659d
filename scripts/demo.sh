#!/usr/bin/env bash
# The main job: installs what is missing, builds the release preset, then
#   - lists the Vulkan devices,
#   - describes the bundled sample capture,
#   - simulates every bundled scene (harness/scenes) into a capture sequence under
#     out/demo/captures (only when that capture is missing),
#   - replays every capture through the effects it declares (glint run, reflections with the
#     denoiser and the composite) into out/demo/runs, and writes out/demo/report.html
#     (images side by side, errors against the references, per-pass times, the device),
#   - measures the depth pyramid at 1920x1080 and SSSR on the glossy room at 640x360 on the
#     selected device (per-pass times, traced fraction, how the rays ended),
# and writes the text results to out/report.md. GLINT_OUT moves out/, GLINT_DEVICE picks the device.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" release glint glint_make_sample
cd "$root"
bin=build/release/harness
glint="$bin/cli/glint"
out=${GLINT_OUT:-out}
mkdir -p "$out/demo/captures" "$out/demo/runs"
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
  echo "## Bundled scenes (glint simulate when missing, then glint run)"
  runs=()
  for scene in harness/scenes/*.toml; do
    name=$(basename "$scene" .toml)
    echo
    echo "### $name"
    echo '```'
    if [ ! -f "$out/demo/captures/$name/manifest.json" ]; then
      "$glint" simulate "$scene" --out "$out/demo/captures/$name"
    fi
    "$glint" run "$out/demo/captures/$name" --out "$out/demo/runs/$name" --set denoise=true --set composite=true 2>/dev/null
    echo '```'
    runs+=("$out/demo/runs/$name")
  done
  echo
  "$glint" report "${runs[@]}" --out "$out/demo/report.html" --title "glint demo: the bundled scenes"
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
echo "demo: wrote $out/demo/report.html, $out/report.md and the captures under $out/demo/captures"
