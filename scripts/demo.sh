#!/usr/bin/env bash
# The main job: installs what is missing, builds the release preset, then lists the Vulkan
# devices and describes the bundled sample capture. Output goes to out/ (report.md).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" release glint glint_make_sample
cd "$root"
bin=build/release/harness
out=${GLINT_OUT:-out}
mkdir -p "$out"
"$bin/capture/glint_make_sample" "$out"
{
  echo "# glint demo report"
  echo
  echo '```'
  "$bin/cli/glint" devices
  echo
  "$bin/cli/glint" info "$out/sample"
  echo '```'
} | tee "$out/report.md"
echo "demo: wrote $out/report.md"
