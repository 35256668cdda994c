#!/usr/bin/env bash
# Usage: time_limit.sh WAVETRACE SCENE
# A time limit far shorter than one pass: the render stops after its first pass (1 spp), writes
# the image and says how many spp it reached.
set -eu
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out=$("$wavetrace" render "$scene" --width 32 --height 24 --spp 100000 --time-limit 0.000001 -o "$work/a.png" 2>/dev/null)
echo "$out"
case "$out" in *"stopped by the time limit at 1 of 100000 spp"*) ;; *) echo "FAIL: no time-limit stop in the summary"; exit 1 ;; esac
case "$out" in *"32x24, 1 spp"*) ;; *) echo "FAIL: the summary does not give the spp reached"; exit 1 ;; esac
[ -s "$work/a.png" ] || { echo "FAIL: no image"; exit 1; }
