#!/usr/bin/env bash
# Usage: checkpoint_errors.sh WAVETRACE SCENE
# Every bad checkpoint, resume and merge through the real command line: a message naming the
# file and the problem, exit 1, the files already there unchanged and nothing new written.
# And a full disk during checkpoints (a file size limit): warnings, the render goes on, the
# previous checkpoint stays.
source "$(dirname "$0")/script_setup.sh"
size=(--width 32 --height 24 --threads 2 -q)
cd "$work"

# expect_fail SUBSTRING COMMAND...: exit 1 with SUBSTRING in the output, and no new files.
expect_fail() {
  local expected=$1
  shift
  local before after output status
  before=$(ls -A | sort | xargs -r md5sum)
  output=$("$@" 2>&1)
  status=$?
  after=$(ls -A | sort | xargs -r md5sum)
  [ "$status" -eq 1 ] || fail "exit $status (expected 1) for: $*"$'\n'"$output"
  case "$output" in *"$expected"*) ;; *) fail "no '$expected' in the output of: $*"$'\n'"$output" ;; esac
  [ "$before" = "$after" ] || fail "files changed by: $*"$'\n'"$before"$'\n'"---"$'\n'"$after"
  echo "ok: $(echo "$output" | head -n 1)"
}

"$wavetrace" render "$scene" "${size[@]}" --spp 8 -o good.ckpt -o good.png || fail "a good checkpoint"
bytes=$(stat -c %s good.ckpt)
head -c $((bytes / 2)) good.ckpt >truncated.ckpt
cp good.ckpt corrupted.ckpt
printf '\x55' | dd of=corrupted.ckpt bs=1 seek=$((bytes / 2)) conv=notrunc status=none
cp good.png image.ckpt

expect_fail "missing.ckpt: cannot open" "$wavetrace" render "$scene" "${size[@]}" --resume missing.ckpt
expect_fail "truncated.ckpt: truncated: the header describes $bytes bytes, the file has $((bytes / 2))" \
  "$wavetrace" render "$scene" "${size[@]}" --resume truncated.ckpt
expect_fail "corrupted.ckpt: checksum mismatch" "$wavetrace" render "$scene" "${size[@]}" --resume corrupted.ckpt
expect_fail "image.ckpt: not a wavetrace checkpoint" "$wavetrace" render "$scene" "${size[@]}" --resume image.ckpt
expect_fail "good.ckpt: not a checkpoint of this render: seed: checkpoint 0, this render 5" \
  "$wavetrace" render "$scene" "${size[@]}" --resume good.ckpt --seed 5
expect_fail "size: checkpoint 32x24, this render 32x25" "$wavetrace" render "$scene" --width 32 --height 25 -q --resume good.ckpt
expect_fail "fresnel: checkpoint schlick, this render exact" "$wavetrace" render "$scene" "${size[@]}" --fresnel exact --resume good.ckpt
expect_fail "sampler: checkpoint stratified, this render sobol" "$wavetrace" render "$scene" "${size[@]}" --sampler sobol --resume good.ckpt
expect_fail "--spp 4: good.ckpt holds samples up to 8 already" "$wavetrace" render "$scene" "${size[@]}" --resume good.ckpt --spp 4
expect_fail "a checkpoint's name must end in .ckpt" "$wavetrace" render "$scene" "${size[@]}" --checkpoint state.png
expect_fail "directory 'nowhere' does not exist" "$wavetrace" render "$scene" "${size[@]}" --checkpoint nowhere/c.ckpt
expect_fail "no --samples with it" "$wavetrace" render "$scene" "${size[@]}" --resume good.ckpt --samples 0:4
expect_fail "--samples 5:5: need 0 <= BEGIN < END" "$wavetrace" render "$scene" "${size[@]}" --samples 5:5
expect_fail "--samples: expected BEGIN:END" "$wavetrace" render "$scene" "${size[@]}" --samples 5-9

"$wavetrace" render "$scene" "${size[@]}" --spp 8 --samples 0:4 -o a.ckpt || fail "part a"
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --samples 3:6 -o b.ckpt || fail "part b"
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --samples 6:8 -o c.ckpt || fail "part c"
"$wavetrace" render "$scene" "${size[@]}" --spp 8 --samples 4:6 --seed 2 -o seed2.ckpt || fail "part seed2"
expect_fail "a.ckpt (samples 0:4) and b.ckpt (samples 3:6) overlap: samples 3:4 would be counted twice" \
  "$wavetrace" merge c.ckpt b.ckpt a.ckpt -o m.png
expect_fail "samples 4:6 are in none of the parts" "$wavetrace" merge a.ckpt c.ckpt -o m.png
expect_fail "samples 4:6 are missing: a checkpoint of samples 0:8 would claim them" \
  "$wavetrace" merge a.ckpt c.ckpt --allow-gaps -o m.ckpt -o m.png
expect_fail "seed2.ckpt is not a part of the same render as a.ckpt: seed: a.ckpt 0, seed2.ckpt 2" \
  "$wavetrace" merge a.ckpt seed2.ckpt c.ckpt -o m.png
expect_fail "truncated.ckpt: truncated" "$wavetrace" merge a.ckpt truncated.ckpt -o m.png
expect_fail "unsupported image extension" "$wavetrace" merge a.ckpt -o m.txt
"$wavetrace" merge a.ckpt c.ckpt --allow-gaps -o gaps.png -q 2>gaps.log || fail "--allow-gaps"
[ -s gaps.png ] && grep -q "warning: samples 4:6 are in none of the parts" gaps.log || fail "--allow-gaps: no image or no warning"

# A full disk during checkpoints: every write fails, the render finishes, the image is written,
# the old checkpoint stays as it was, and the run ends in an error naming the checkpoint.
cp good.ckpt full.ckpt
status=0
output=$( (ulimit -f 16; "$wavetrace" render "$scene" --width 96 --height 72 --threads 2 --spp 64 --checkpoint full.ckpt \
  --checkpoint-every 0.001 -o full.png) 2>&1) || status=$?
[ "$status" -eq 1 ] || fail "full disk: exit $status, expected 1"$'\n'"$output"
case "$output" in *"warning: full.ckpt: cannot write: File too large (the previous checkpoint stays)"*) ;; *) fail "full disk: no warning"$'\n'"$output" ;; esac
case "$output" in *"full.ckpt: the final checkpoint could not be written (the images were)"*) ;; *) fail "full disk: no final error"$'\n'"$output" ;; esac
warnings=$(echo "$output" | grep -c "cannot write")
[ "$warnings" -ge 2 ] || fail "full disk: $warnings failed writes, expected one per pass and the final one"
cmp -s full.ckpt good.ckpt || fail "full disk: the previous checkpoint changed"
[ -s full.png ] || fail "full disk: no image"
[ -z "$(ls -A | grep tmp)" ] || fail "full disk: temporaries left: $(ls -A)"
echo "ok: full disk: $warnings failed checkpoint writes reported, the render finished, the old checkpoint intact"
