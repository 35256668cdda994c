#!/usr/bin/env bash
# Usage: texture_smoke.sh WAVETRACE SCENE
# A textured scene through the real command line: it renders, and the texture memory is printed.
set -eu
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$("$wavetrace" render "$scene" --width 16 --height 12 --spp 2 --threads 2 -o "$work/a.png" 2>&1)
echo "$out"
case "$out" in *"wavetrace: textures: 1 image, "*) ;; *) echo "FAIL: no texture memory line"; exit 1 ;; esac
case "$out" in *"NaN/Inf samples  0"*) ;; *) echo "FAIL: NaN/Inf samples"; exit 1 ;; esac
[ -s "$work/a.png" ] || { echo "FAIL: image missing"; exit 1; }
