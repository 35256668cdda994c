#!/usr/bin/env bash
# Usage: image_module_missing.sh WAVETRACE SCENE
# wavetrace copied away from its image I/O module: --help still works (it needs no image
# library); EXR and PNG images, written without the module (src/core/image_io/
# direct_image_output.h), are written; a render to a format the module writes (.jpg) stops
# before rendering with a message naming the module it looked for.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$1" "$work/wavetrace"
"$work/wavetrace" --help >/dev/null || { echo "FAIL: --help failed without the module"; exit 1; }

output=$(cd "$work" && ./wavetrace render "$2" --width 4 --height 4 --spp 1 -o out.png -o out.exr 2>&1)
status=$?
echo "$output"
[ "$status" -eq 0 ] || { echo "FAIL: a render to .png and .exr without the module: exit status $status"; exit 1; }
[ -s "$work/out.png" ] && [ -s "$work/out.exr" ] || { echo "FAIL: the .png or the .exr was not written"; exit 1; }

output=$(cd "$work" && ./wavetrace render "$2" --width 4 --height 4 --spp 1 -o out.jpg 2>&1)
status=$?
echo "$output"
[ "$status" -ne 0 ] && [ "$status" -lt 128 ] || { echo "FAIL: exit status $status"; exit 1; }
case "$output" in
  *"cannot load the image I/O module $work/libwavetrace_image_io.so"*) ;;
  *) echo "FAIL: the message does not name the module"; exit 1 ;;
esac
case "$output" in *"wall time"*) echo "FAIL: it rendered first"; exit 1 ;; esac
[ ! -e "$work/out.jpg" ] || { echo "FAIL: wrote an image"; exit 1; }
