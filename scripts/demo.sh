#!/usr/bin/env bash
# The main job: installs what is missing, builds the release preset, then
#   - lists the Vulkan devices,
#   - describes the bundled sample capture,
#   - simulates every bundled scene (harness/scenes) into a capture sequence under
#     out/demo/captures at GLINT_DEMO_SIZE for GLINT_DEMO_FRAMES frames (default 16, so the
#     temporal denoisers converge, or the scene's own frame count where it is larger: the scenes
#     written to show motion play out), with references of GLINT_DEMO_SPP samples per pixel a
#     frame that accumulate over frames whose scene and camera are unchanged, and, for the
#     reflections, more samples (up to GLINT_DEMO_MAX_SPP a frame) on the scored pixels (GGX
#     alpha below 0.2) whose relative standard error is still above GLINT_DEMO_NOISE_TARGET;
#     scenes of shadows alone take GLINT_DEMO_SHADOW_SPP a frame (they trace no reflection or
#     shading rays); then again with an independent seed (2) for the reference noise floor. The
#     defaults follow the selected device: on a CPU (lavapipe) 320x180, 8, 24, 0.005 and 32, sized to
#     finish within ten minutes on two cores (docs/performance.md, "The demo's simulations on
#     a 2-core machine"); on a discrete GPU 960x540, 64, 256, 0.001 and 256. A capture is simulated
#     again only when its scene file, the simulator or these settings changed (demo_key in its
#     folder),
#   - replays every capture through the effects it declares (glint run, reflections with the
#     denoiser and the composite, --second-reference for the noise floor) into out/demo/runs,
#     scores every frame with LDR-FLIP (scripts/run_flip.py in build/venv, which
#     scripts/python_env.sh makes; skipped, with one line saying so, where it cannot be made),
#     and writes out/demo/report.html (on top a summary table over every scene and effect: noisy
#     and output error, the reference floor and whether the references resolve the difference,
#     FLIP, moving edges, GPU time; then per scene the noisy input, output and reference where the
#     error is largest, enlarged, the whole frame's images, the metric in words, error and FLIP
#     against frame of the noisy input, the output and the reference noise floor, per-pass times,
#     the FidelityFX anchor points with their conditions, the device),
#   - measures the depth pyramid at 1920x1080 and SSSR on the glossy room at 640x360 on the
#     selected device (per-pass times, traced fraction, how the rays ended),
# and writes the text results to out/report.md. GLINT_OUT moves out/, GLINT_DEVICE picks the device,
# GLINT_DEMO_SCENES (space-separated names) limits the scenes. A line "[step/steps] ..." on stderr
# says what it is doing.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" release glint glint_make_sample
cd "$root"
bin=build/release/harness
glint="$bin/cli/glint"
out=${GLINT_OUT:-out}
# Bigger defaults where the selected device is a discrete GPU.
if "$glint" devices 2>/dev/null | grep -A1 '^\*' | head -n 1 | grep -q '(discrete GPU)'; then
  size=${GLINT_DEMO_SIZE:-960x540} spp=${GLINT_DEMO_SPP:-64} max_spp=${GLINT_DEMO_MAX_SPP:-256}
  shadow_spp=${GLINT_DEMO_SHADOW_SPP:-256}
  noise_target=${GLINT_DEMO_NOISE_TARGET:-0.001}
else
  size=${GLINT_DEMO_SIZE:-320x180} spp=${GLINT_DEMO_SPP:-8} max_spp=${GLINT_DEMO_MAX_SPP:-24}
  shadow_spp=${GLINT_DEMO_SHADOW_SPP:-32}
  noise_target=${GLINT_DEMO_NOISE_TARGET:-0.005}
fi
frames=${GLINT_DEMO_FRAMES:-16}
mkdir -p "$out/demo/captures" "$out/demo/runs"
scenes=()
for scene in harness/scenes/*.toml; do
  name=$(basename "$scene" .toml)
  if [ -n "${GLINT_DEMO_SCENES:-}" ] && [[ " $GLINT_DEMO_SCENES " != *" $name "* ]]; then continue; fi
  scenes+=("$scene")
done
if [ ${#scenes[@]} -eq 0 ]; then
  echo "demo: GLINT_DEMO_SCENES='${GLINT_DEMO_SCENES:-}' names no scene of harness/scenes" >&2
  exit 2
fi
# Per scene: two simulations and a run; then FLIP, the report and the two benchmarks.
steps=$((3 * ${#scenes[@]} + 4))
step=0
started=$SECONDS
progress() {
  step=$((step + 1))
  printf '[%d/%d] %s (%ds elapsed)\n' "$step" "$steps" "$1" $((SECONDS - started)) >&2
}
# The frames scene $1 is simulated for: GLINT_DEMO_FRAMES when set, else 16 or the scene's own
# `frames = N`, whichever is larger.
scene_frames() {
  local own
  own=$(sed -n 's/^frames *= *\([0-9][0-9]*\).*/\1/p' "$1" | head -n 1)
  if [ -z "${GLINT_DEMO_FRAMES:-}" ] && [ -n "$own" ] && [ "$own" -gt "$frames" ]; then
    echo "$own"
  else
    echo "$frames"
  fi
}
# Simulates scene $1 with seed $2 into $3 unless $3 holds a capture of the same scene file,
# size, frame count, sample count and seed.
simulate() {
  local scene=$1 seed=$2 dir=$3
  local key count samples=$spp
  count=$(scene_frames "$scene")
  # A scene of shadows alone traces no reflection or shading rays: its references take more.
  if grep -q '^effects *= *\["shadows"\]' "$scene"; then samples=$shadow_spp; fi
  key="$(sha1sum <"$scene" | cut -d' ' -f1) glint=$glint_id size=$size frames=$count spp=$samples max=$max_spp target=$noise_target seed=$seed"
  if [ -f "$dir/manifest.json" ] && [ "$(cat "$dir/demo_key" 2>/dev/null)" = "$key" ]; then
    progress "$(basename "$scene" .toml): capture with seed $seed is up to date"
    return
  fi
  progress "simulating $(basename "$scene" .toml), $size, $count frames, reference seed $seed at $samples spp a frame (up to $max_spp)"
  rm -rf "$dir"
  "$glint" simulate "$scene" --out "$dir" --size "$size" --frame-count "$count" --seed "$seed" --spp "$samples" \
    --max-spp "$max_spp" --noise-target "$noise_target" --noise-target-alpha-below 0.2
  echo "$key" >"$dir/demo_key"
}
# A capture is reused only when the scene, the settings and the simulator that made it are the same.
glint_id=$(sha1sum <"$glint" | cut -d' ' -f1)
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
  echo "## Bundled scenes at $size, $frames frames or the scene's own count where larger (glint simulate when changed, then glint run)"
  runs=()
  for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .toml)
    echo
    echo "### $name"
    echo '```'
    simulate "$scene" 1 "$out/demo/captures/$name"
    simulate "$scene" 2 "$out/demo/captures/$name.seed2"
    progress "running $name"
    "$glint" run "$out/demo/captures/$name" --out "$out/demo/runs/$name" --set denoise=true --set composite=true \
      --second-reference "$out/demo/captures/$name.seed2" 2>/dev/null
    echo '```'
    runs+=("$out/demo/runs/$name")
  done
  echo
  # LDR-FLIP per frame (scripts/run_flip.py) into each run's summary.json, for the report. It
  # needs build/venv (scripts/python_env.sh makes it, from the network the first time); without
  # it the report shows "-" for FLIP.
  progress "scoring every frame with LDR-FLIP (scripts/run_flip.py)"
  echo "## LDR-FLIP of the runs (scripts/run_flip.py)"
  echo '```'
  if scripts/python_env.sh >&2; then
    if ! build/venv/bin/python scripts/run_flip.py "${runs[@]}"; then
      echo "demo: scripts/run_flip.py failed: the report shows no FLIP"
    fi
  else
    echo "demo: FLIP skipped: scripts/python_env.sh could not make build/venv (flip-evaluator, numpy)"
  fi
  echo '```'
  echo
  progress "writing $out/demo/report.html"
  "$glint" report "${runs[@]}" --out "$out/demo/report.html" --title "glint demo: the bundled scenes" \
    --anchors docs/anchors/fidelityfx-sdk-1.1.4.json
  echo
  progress "benchmarking the depth pyramid"
  echo "## Depth pyramid, 1920x1080 (glint bench)"
  echo '```'
  "$glint" bench depth_pyramid --size 1920x1080 --runs 20
  echo '```'
  echo
  progress "benchmarking the reflections"
  echo "## Stochastic screen-space reflections and their denoiser, glossy room 640x360 (glint bench reflections)"
  echo '```'
  "$glint" bench reflections --size 640x360 --runs 10 --set denoise=true
  echo '```'
} | tee "$out/report.md"
echo "demo: $((SECONDS - started)) s; wrote $out/demo/report.html, $out/report.md and the captures under $out/demo/captures"
