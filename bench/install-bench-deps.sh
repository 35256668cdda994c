#!/usr/bin/env bash
# Installs the Debian 12 packages only the benchmarks use, skipping any already there (`make
# bench` runs it; the default build, the tests and CI need none of them):
#   libembree-dev       Embree 3, the baseline bench_intersect compares our BVH and kernels with
#   assimp-testmodels   the real model of the hexroom_2cylinderengine scene
#                       (/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb)
# Re-run cmake after it (make bench does) so CMake finds Embree.
set -euo pipefail

packages=(libembree-dev assimp-testmodels)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "wavetrace bench: installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "wavetrace bench: not root and no sudo; install them with: apt-get install ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt_wait=(-o DPkg::Lock::Timeout=600)
"${sudo[@]}" apt-get "${apt_wait[@]}" update -qq
"${sudo[@]}" apt-get "${apt_wait[@]}" install -y -qq --no-install-recommends "${missing[@]}"
