#!/usr/bin/env bash
# Usage: tradeoff_smoke.sh WAVETRACE SCENE
# The trade tool on a tiny render of SCENE: a reference made first (seed 1, many spp), then a
# sweep of two knobs at three spp. The CSV must have a row per configuration and spp, every
# configuration's error must fall from the lowest spp to the highest, and the fits CSV and the
# table must name every configuration.
set -eu
wavetrace=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size=(--width 16 --height 16)
"$wavetrace" render "$scene" "${size[@]}" --spp 2048 --seed 1 --threads 2 -q -o "$work/ref.exr"
table=$("$wavetrace" tradeoff "$scene" "${size[@]}" --reference "$work/ref.exr" --spp 4,16,64 --repeats 1 --threads 2 \
        --knobs shadow_rays,fresnel --csv "$work/points.csv" --fits-csv "$work/fits.csv")
echo "$table"
# base (1 shadow ray), shadow_rays 2 3 4 8, fresnel exact: 6 configurations x 3 spp
rows=$(($(wc -l < "$work/points.csv") - 1))
[ "$rows" -eq 18 ] || { echo "FAIL: $rows measurement rows, expected 18"; cat "$work/points.csv"; exit 1; }
[ "$(($(wc -l < "$work/fits.csv") - 1))" -eq 6 ] || { echo "FAIL: fits rows"; cat "$work/fits.csv"; exit 1; }
awk -F, 'NR > 1 { if ($5 == 4) low[$1] = $9; if ($5 == 64) high[$1] = $9 }
         END { n = 0; for (c in low) { n++; if (!(high[c] < 0.7 * low[c])) { print "FAIL: " c " RMSE " low[c] " -> " high[c]; bad = 1 } }
               exit bad || n != 6 }' "$work/points.csv" || { cat "$work/points.csv"; exit 1; }
for c in base shadow_rays=3 shadow_rays=8 fresnel=exact "Pareto front"; do
  case "$table" in *"$c"*) ;; *) echo "FAIL: the table does not name $c"; exit 1 ;; esac
done
[ "$(ls -A "$work" | sort | tr '\n' ' ')" = "fits.csv points.csv ref.exr " ] || { echo "FAIL: stray files"; ls -la "$work"; exit 1; }
