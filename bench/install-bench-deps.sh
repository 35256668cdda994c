#!/usr/bin/env bash
# Installs the Debian 12 packages only the benchmarks use, skipping any already there (`make
# bench` runs it; the default build, the tests and CI need none of them):
#   libembree-dev       Embree 3, the baseline bench_intersect compares our BVH and kernels with
#   assimp-testmodels   the real model of the hexroom_2cylinderengine scene
#                       (/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb)
# Re-run cmake after it (make bench does) so CMake finds Embree.
set -euo pipefail
exec "$(dirname "$0")/../tools/install-deps.sh" libembree-dev assimp-testmodels
