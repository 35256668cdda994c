#!/usr/bin/env bash
# Usage: bench/many_lights_sweep.sh WAVETRACE OUT_DIR [SPP] [SIDES...]
# Light selection against the number of emitters: for each side N of the many-lights scene
# (bench/make_many_lights_scene.py --side N: N^2 ceiling triangles and a band on each wall),
# renders area, power and bvh at SPP and prints, per selection, the CPU time (user + system)
# and the image's mean variance of the pixel mean (the `variance` AOV, no reference needed),
# and their product relative to area's: the time each needs for the same noise (below 1 pays).
set -euo pipefail
wavetrace=$1 out=$2 spp=${3:-64}
shift $(( $# < 3 ? $# : 3 ))
sides=("$@")
[ ${#sides[@]} -gt 0 ] || sides=(2 4 8 16 32 80)
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
printf "%-6s %-9s %-6s %10s %14s %12s\n" side emitters how cpu_s mean_variance time_x_var
for side in "${sides[@]}"; do
  scene=$out/many_lights_$side.json
  emitters=$("$here/make_many_lights_scene.py" "$scene" --side "$side" | awk '{print $2}')
  area_product=""
  for how in area power bvh; do
    exr=$out/${side}_$how.exr
    /usr/bin/time -f "%U %S" -o "$out/time.txt" "$wavetrace" render "$scene" --spp "$spp" --threads 2 \
      --light-selection "$how" --aov variance -o "$exr" >/dev/null 2>&1
    cpu=$(awk '{print $1 + $2}' "$out/time.txt")
    # The mean over pixels of the variance AOV's three channels (the last three before "(float)").
    variance=$(oiiotool --stats "$exr" 2>/dev/null | awk '/Stats Avg/ { print ($(NF-3) + $(NF-2) + $(NF-1)) / 3 }')
    product=$(awk -v c="$cpu" -v v="$variance" 'BEGIN { printf "%.6g", c * v }')
    [ -n "$area_product" ] || area_product=$product
    relative=$(awk -v p="$product" -v a="$area_product" 'BEGIN { printf "%.3f", p / a }')
    printf "%-6s %-9s %-6s %10.2f %14.6g %12s\n" "$side" "$emitters" "$how" "$cpu" "$variance" "$relative"
  done
done
