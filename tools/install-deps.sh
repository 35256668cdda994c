#!/usr/bin/env bash
# Installs the Debian 12 packages wavetrace needs to build and test, and any named as arguments,
# skipping any already there. Safe to run again; does nothing when everything is installed.
set -euo pipefail

packages=(
  g++ cmake make                # toolchain
  libglm-dev                    # vector maths
  libopenimageio-dev            # images read (textures, references) and written as .hdr, .jpg
  libopenexr-dev                # .exr written (without loading OpenImageIO: src/core/image_io/direct_image_output.h)
  libpng-dev                    # .png written (the same)
  openimageio-tools             # Debian 12's OpenImageIO CMake targets name /usr/bin/iconvert and friends
  libopencv-core-dev            # Debian 12's OpenImageIO CMake target names /usr/include/opencv4
  nlohmann-json3-dev            # scene files
  libcli11-dev                  # command line
  libtinyobjloader-dev          # mesh files: OBJ and MTL
  libtinygltf-dev               # mesh files: glTF 2.0 (.gltf, .glb)
  libgtest-dev                  # tests
  libbenchmark-dev              # benchmarks
  python3                       # tools/check_layers.py: the include-layer check (ctest layers.*)
  valgrind                      # callgrind, for the instruction-count performance gate
  libxxhash-dev                 # the checkpoint checksum (XXH3-64)
  python3-matplotlib            # tools/plot_tradeoff.py: the error-against-time plot of `wavetrace tradeoff`
  fonts-dejavu-core             # tools/spp_series.sh: oiiotool --text needs a font file to label docs/spp_series.png
)
# Extra packages named on the command line (bench/install-bench-deps.sh: the benchmarks' own).
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "wavetrace: installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "wavetrace: not root and no sudo; install them with: apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
# Wait for another apt (unattended upgrades on a fresh machine) instead of failing at once.
apt_wait=(-o DPkg::Lock::Timeout=600)
"${sudo[@]}" apt-get "${apt_wait[@]}" update -qq
"${sudo[@]}" apt-get "${apt_wait[@]}" install -y -qq --no-install-recommends "${missing[@]}"
