#!/usr/bin/env bash
# Unpacks Mesa's lavapipe from bookworm-backports (Mesa 25, with VK_KHR_acceleration_structure
# and VK_KHR_ray_query) into a folder, beside the system's driver, and writes an ICD file there
# that names it by absolute path. Tests select it with
#   VK_DRIVER_FILES=<folder>/lvp_icd.json LD_LIBRARY_PATH=<folder>/lib
# Nothing is installed: apt runs with its own source list and state inside the folder, so the
# system's package lists and its lavapipe stay as they are. Idempotent: returns at once when
# the folder holds the version it asks for.
#   scripts/lavapipe_rayquery.sh <folder>
set -euo pipefail
folder=${1:?usage: scripts/lavapipe_rayquery.sh <folder>}
# The packages bookworm lacks: lavapipe itself and the libdrm it was built against (it links
# libLLVM-15, which bookworm has: libllvm15 is installed with mesa-vulkan-drivers).
packages=(mesa-vulkan-drivers libdrm2)
suite=bookworm-backports
stamp="$folder/packages.txt"
want="$suite: ${packages[*]}"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ] && [ -f "$folder/lvp_icd.json" ]; then
  exit 0
fi

mkdir -p "$folder"
folder=$(cd "$folder" && pwd)
apt_dir="$folder/apt"
rm -rf "$apt_dir" "$folder/root" "$folder/lib"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/debs"
echo "deb [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main" \
  >"$apt_dir/sources.list"
apt_options=(
  -o "Dir::Etc::SourceList=$apt_dir/sources.list" -o Dir::Etc::SourceParts=/dev/null
  -o "Dir::State::Lists=$apt_dir/lists" -o "Dir::Cache=$apt_dir/cache"
  -o APT::Sandbox::User=root -q
)
echo "setup: fetching lavapipe with ray queries from $suite into $folder"
apt-get "${apt_options[@]}" update >/dev/null
names=()
for package in "${packages[@]}"; do names+=("$package/$suite"); done
(cd "$apt_dir/debs" && apt-get "${apt_options[@]}" download "${names[@]}" >/dev/null)
for deb in "$apt_dir/debs"/*.deb; do dpkg-deb -x "$deb" "$folder/root"; done

# Only lavapipe and libdrm are kept; the other drivers in the package are not used.
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
mkdir -p "$folder/lib"
cp -a "$folder/root/usr/lib/$multiarch/libvulkan_lvp.so" "$folder/root/usr/lib/$multiarch"/libdrm.so.2* "$folder/lib/"
api_version=$(sed -n 's/.*"api_version": *"\([^"]*\)".*/\1/p' "$folder/root/usr/share/vulkan/icd.d/lvp_icd.json")
cat >"$folder/lvp_icd.json" <<JSON
{
    "file_format_version": "1.0.0",
    "ICD": {
        "library_path": "$folder/lib/libvulkan_lvp.so",
        "api_version": "$api_version"
    }
}
JSON
rm -rf "$folder/root" "$apt_dir"
missing=$(LD_LIBRARY_PATH="$folder/lib" ldd "$folder/lib/libvulkan_lvp.so" | sed -n 's/^\s*\(\S*\) => not found/\1/p' | tr '\n' ' ')
if [ -n "$missing" ]; then
  echo "setup: $folder/lib/libvulkan_lvp.so needs libraries this system lacks: $missing" >&2
  exit 1
fi
echo "$want" >"$stamp"
