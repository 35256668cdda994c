#!/usr/bin/env bash
# Usage: estimator_flags.sh WAVETRACE SCENE
# The estimator flags (--sampler, --light-sampling, --clamp-indirect) are the scene settings of
# the same names: a render with the flags and one of a copy of the scene with the settings give
# the same image, and the flags change the image.
set -eu
# Radiance .hdr, not .exr: an EXR header carries the time it was written.
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed 's/"render": {/"render": {"sampler": "sobol", "light_sampling": "mis", "clamp_indirect": 2.5, /' "$scene" > "$work/scene.json"
grep -q '"sampler": "sobol"' "$work/scene.json" || { echo "FAIL: could not write the scene copy"; exit 1; }
common=(--width 16 --height 12 --spp 4 --threads 2 -q)
"$wavetrace" render "$scene" "${common[@]}" -o "$work/default.hdr"
"$wavetrace" render "$scene" "${common[@]}" --sampler sobol --light-sampling mis --clamp-indirect 2.5 -o "$work/flags.hdr"
"$wavetrace" render "$work/scene.json" "${common[@]}" -o "$work/settings.hdr"
cmp "$work/flags.hdr" "$work/settings.hdr" || { echo "FAIL: flags and scene settings differ"; exit 1; }
if cmp -s "$work/flags.hdr" "$work/default.hdr"; then echo "FAIL: the flags changed nothing"; exit 1; fi
# A sample replays with the options too.
replay=$("$wavetrace" render "$work/scene.json" --width 16 --height 12 --spp 4 --debug-sample 8,6,3)
case "$replay" in *"bounce 0"*"radiance ("*) ;; *) echo "FAIL: replay printed no path"; echo "$replay"; exit 1 ;; esac
echo ok
