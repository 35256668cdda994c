#!/usr/bin/env bash
# Usage: aov_resume.sh WAVETRACE SCENE
# The AOVs live in the film, so they are checkpointed: 4 spp resumed to 8 gives the EXR (beauty
# and every layer) of a straight 8-spp render, value for value; a resume that asks for other
# AOVs than the checkpoint holds is refused, naming the channels; merged parts keep them.
set -eu
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
size=(--width 16 --height 12)
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --aov all -q -o "$work/straight.exr"
"$wavetrace" render "$scene" "${size[@]}" --spp 4 --aov all -q --checkpoint "$work/c.ckpt" -o "$work/half.png"
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --aov all -q --resume "$work/c.ckpt" -o "$work/resumed.exr"
oiiotool --fail 0 --warn 0 --diff "$work/straight.exr" "$work/resumed.exr" || { echo "FAIL: the resumed AOVs differ"; exit 1; }
if out=$("$wavetrace" render "$scene" "${size[@]}" --spp 12 -q --resume "$work/c.ckpt" -o "$work/x.png" 2>&1); then
  echo "FAIL: resumed without the checkpoint's AOVs"; exit 1
fi
echo "$out"
case "$out" in *"extra channels"*"albedo.R"*) ;; *) echo "FAIL: the message does not name the channels"; exit 1 ;; esac
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --aov depth -q --samples 0:3 -o "$work/p1.ckpt"
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --aov depth -q --samples 3:8 -o "$work/p2.ckpt"
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --aov depth -q -o "$work/depth.exr"
"$wavetrace" merge "$work/p2.ckpt" "$work/p1.ckpt" -q -o "$work/merged.exr"
oiiotool --fail 0 --warn 0 --diff "$work/depth.exr" "$work/merged.exr" || { echo "FAIL: the merged depth differs"; exit 1; }
oiiotool --info -v "$work/merged.exr" | grep -q 'wavetrace:spp: 8' || { echo "FAIL: merged spp"; exit 1; }
