#!/usr/bin/env bash
# Installs whatever system packages are missing, then configures and builds one preset.
# Idempotent: with everything installed and built, it checks and returns in seconds.
#   scripts/setup.sh <debug|release|fuzz> [target...]
set -euo pipefail
preset=${1:?usage: scripts/setup.sh <debug|release|fuzz>}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Debian bookworm package names; every dependency of the project is in this list.
packages=(
  cmake ninja-build g++ pkg-config git clang-format
  libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers vulkan-tools
  glslang-tools spirv-tools spirv-cross libspirv-cross-c-shared-dev
  libopenexr-dev libimath-dev libpng-dev catch2 libcli11-dev nlohmann-json3-dev libtomlplusplus-dev
  libassimp-dev assimp-testmodels
  libglfw3-dev libimgui-dev xvfb xauth
)
# The fuzz preset (scripts/fuzz.sh) also needs clang with libFuzzer and its sanitizer
# runtimes, and llvm-symbolizer (llvm-14) for readable sanitizer reports.
if [ "$preset" = fuzz ]; then
  packages+=(clang libclang-rt-14-dev llvm-14)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then sudo=(sudo); fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# The debug preset's ray-query tests (tests/hybrid, label rayquery) run on Mesa 25's lavapipe
# from bookworm-backports; bookworm's own (Mesa 22.3) has no ray queries. It is unpacked beside
# the system driver, never installed over it (scripts/lavapipe_rayquery.sh, CONTRIBUTING.md).
# Without it (no network) the rest of the suite still runs and those tests skip, except in CI.
if [ "$preset" = debug ] && ! "$root/scripts/lavapipe_rayquery.sh" "$root/build/lavapipe-rayquery"; then
  if [ "${CI:-}" = true ] || [ -n "${GLINT_FORBID_SKIPS:-}" ]; then
    exit 1
  fi
  echo "setup: no ray-query lavapipe in build/lavapipe-rayquery: the rayquery tests will skip"
fi

cd "$root"
# GLINT_CONFIGURE_ARGS (cache settings, e.g. -DGLINT_DXC_TESTS=<dxc>) configure the preset
# again; without them an existing build keeps its configuration.
read -r -a configure_args <<<"${GLINT_CONFIGURE_ARGS:-}"
if [ ! -f "build/$preset/CMakeCache.txt" ] || ((${#configure_args[@]})); then
  cmake --preset "$preset" "${configure_args[@]}"
fi
# Optional targets after the preset limit the build to what the caller runs.
cmake --build --preset "$preset" ${2:+--target "${@:2}"}
# The test suite also runs scripts/study.py (tests/cli/study_python.cmake).
if [ "$preset" = debug ]; then
  "$root/scripts/python_env.sh"
fi
