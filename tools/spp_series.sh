#!/usr/bin/env bash
# Usage: spp_series.sh WAVETRACE SCENE REFERENCE OUT.png
# The same view at 1, 4, 16 and 64 spp side by side (the seed report's Figure 3.1), each
# rendered at the reference's resolution, shown at twice its size and labelled with its spp, its
# render time (one run on 2 threads: a shared machine's time is noisy) and its RMSE against
# REFERENCE. oiiotool (Debian's openimageio-tools) scales, labels and montages.
set -euo pipefail
wavetrace=$1 scene=$2 reference=$3 out=$4
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf  # fonts-dejavu-core: oiiotool --text needs a font file
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
read -r width height < <(iinfo "$reference" | awk '{ print $3, $5 }' | tr -d ',')
tiles=()
for spp in 1 4 16 64; do
  log=$("$wavetrace" render "$scene" --width "$width" --height "$height" --spp "$spp" --threads 2 \
        --reference "$reference" -o "$work/$spp.png")
  seconds=$(echo "$log" | awk '$1 == "wall" { printf "%.2f", $3 }')
  rmse=$(echo "$log" | sed -n 's/^  error *RMSE \([0-9.e-]*\),.*/\1/p')
  echo "$spp spp: $seconds s, RMSE $rmse"
  tiles+=("$work/$spp.png" --resample "$((2 * width))x$((2 * height))"
          --text:x=10:y=$((2 * height - 12)):size=22:color=1,1,1:shadow=2:font="$font" "$spp spp, $seconds s, RMSE $rmse")
done
oiiotool --nosoftwareattrib "${tiles[@]}" --mosaic:pad=6 4x1 -o "$work/series.png"
mv "$work/series.png" "$out"
echo "wrote $out"
