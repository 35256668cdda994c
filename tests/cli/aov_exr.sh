#!/usr/bin/env bash
# Usage: aov_exr.sh WAVETRACE SCENE
# `--aov all` through the real command line: the EXR holds the beauty, every AOV layer and the
# metadata; the PNG written beside it is the same image as without --aov.
set -eu
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$wavetrace" render "$scene" --width 16 --height 12 --spp 2 --seed 7 -q --aov all -o "$work/a.exr" -o "$work/a.png"
"$wavetrace" render "$scene" --width 16 --height 12 --spp 2 --seed 7 -q -o "$work/plain.png"
info=$(oiiotool --info -v "$work/a.exr")
echo "$info"
for want in "R, G, B" "Z" "N.R, N.G, N.B" "albedo.R, albedo.G, albedo.B" "samples.Y" "variance.R, variance.G, variance.B" \
            "wavetrace:spp: 2" 'wavetrace:seed: "7"' "wavetrace:scene_hash: " "wavetrace:render_seconds: " \
            'wavetrace:version: "'; do
  case "$info" in *"$want"*) ;; *) echo "FAIL: no '$want' in the EXR"; exit 1 ;; esac
done
oiiotool --diff "$work/a.png" "$work/plain.png" || { echo "FAIL: --aov changed the PNG"; exit 1; }
[ "$(oiiotool --info "$work/a.png" | grep -c '3 channel')" -eq 1 ] || { echo "FAIL: the PNG is not RGB"; exit 1; }
