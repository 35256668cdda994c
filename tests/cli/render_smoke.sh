#!/usr/bin/env bash
# Usage: render_smoke.sh WAVETRACE SCENE
# A tiny render through the real command line: both image formats written, the statistics
# printed, no temporary files left, and a single sample replayable with --debug-sample.
set -eu
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$("$wavetrace" render "$scene" --width 16 --height 12 --spp 2 --threads 2 -o "$work/a.png" -o "$work/a.exr")
echo "$out"
for word in "wall time" "samples/s" "rays/s" "NaN/Inf samples  0"; do
  case "$out" in *"$word"*) ;; *) echo "FAIL: no '$word' in the summary"; exit 1 ;; esac
done
[ -s "$work/a.png" ] && [ -s "$work/a.exr" ] || { echo "FAIL: images missing"; exit 1; }
[ "$(ls -A "$work" | wc -l)" -eq 2 ] || { echo "FAIL: stray files"; ls -la "$work"; exit 1; }
replay=$("$wavetrace" render "$scene" --width 16 --height 12 --spp 2 --debug-sample 8,6,1)
echo "$replay"
case "$replay" in *"bounce 0"*"radiance ("*) ;; *) echo "FAIL: replay printed no path"; exit 1 ;; esac
