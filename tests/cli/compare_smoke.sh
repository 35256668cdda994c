#!/usr/bin/env bash
# Usage: compare_smoke.sh WAVETRACE SCENE REFERENCE
# render --reference prints the error and writes its CSV row; compare on the written image gives
# the same RMSE; an image against itself has none; a mask restricts the count.
set -eu
wavetrace=$1 scene=$2 reference=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$("$wavetrace" render "$scene" --width 200 --height 200 --spp 4 --threads 2 -o "$work/a.exr" \
      --reference "$reference" --error-csv "$work/error.csv" 2>&1)
echo "$out"
render_rmse=$(echo "$out" | sed -n 's/^  error *RMSE \([0-9.e-]*\),.*/\1/p')
[ -n "$render_rmse" ] || { echo "FAIL: render printed no error line"; exit 1; }
[ "$(head -n 1 "$work/error.csv")" = "seconds,spp,rmse,rel_mse" ] || { echo "FAIL: CSV header"; cat "$work/error.csv"; exit 1; }
# One row per progressive pass: 1, 2 and 4 spp, in rising time and falling error.
[ "$(tail -n +2 "$work/error.csv" | cut -d, -f2 | tr '\n' ' ')" = "1 2 4 " ] || { echo "FAIL: CSV rows"; cat "$work/error.csv"; exit 1; }
awk -F, 'NR > 2 && !($1 > t && $3 < e) { exit 1 } NR > 1 { t = $1; e = $3 }' "$work/error.csv" ||
  { echo "FAIL: time must rise and error fall from pass to pass"; cat "$work/error.csv"; exit 1; }
case "$out" in *"pass 1: 2 spp"*"RMSE"*) ;; *) echo "FAIL: no per-pass error line"; exit 1 ;; esac

table=$("$wavetrace" compare "$work/a.exr" "$reference")
echo "$table"
compare_rmse=$(echo "$table" | awk '$1 == "overall" { print $2 }')
awk -v a="$render_rmse" -v b="$compare_rmse" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0.05 && d <= 1e-4 * a) }' ||
  { echo "FAIL: render says RMSE $render_rmse, compare says $compare_rmse"; exit 1; }

self=$("$wavetrace" compare "$reference" "$reference")
echo "$self" | awk '$1 == "overall" { exit !($2 == 0) }' || { echo "FAIL: an image against itself has error"; echo "$self"; exit 1; }

oiiotool --pattern constant:color=0 100x200 1 --pattern constant:color=1 200x200 1 --paste +0+0 -o "$work/right_half.exr"
masked=$("$wavetrace" compare "$work/a.exr" "$reference" --mask "$work/right_half.exr")
echo "$masked"
case "$masked" in *"20000 pixels compared"*) ;; *) echo "FAIL: the mask did not keep half the pixels"; exit 1 ;; esac
