#!/usr/bin/env bash
# Usage: adaptive.sh WAVETRACE SCENE
# Adaptive sampling through the real command line: the flags are the scene settings of the
# same names (the same image), the summary says how many pixels stopped and the mean spp, a
# render checkpointed at 16 spp and resumed to 48 is the 48-spp render byte for byte, and what
# cannot be exact is refused with a message naming it: a resume with another threshold, a
# split render (--samples), a merge of adaptive checkpoints.
source "$(dirname "$0")/script_setup.sh"
size=(--width 32 --height 24 --threads 2)
adaptive=(--adaptive-threshold 0.2 --adaptive-min-spp 8)

sed 's/"render": {/"render": {"adaptive_threshold": 0.2, "adaptive_min_spp": 8, /' "$scene" > "$work/scene.json"
grep -q '"adaptive_threshold": 0.2' "$work/scene.json" || fail "could not write the scene copy"
# Radiance .hdr, not .exr: an EXR header carries the time it was written.
"$wavetrace" render "$scene" "${size[@]}" --spp 48 "${adaptive[@]}" -o "$work/flags.hdr" -o "$work/whole.ckpt" >"$work/log" 2>&1 ||
  fail "adaptive render"
"$wavetrace" render "$work/scene.json" "${size[@]}" --spp 48 -q -o "$work/settings.hdr" || fail "render of the scene copy"
"$wavetrace" render "$scene" "${size[@]}" --spp 48 -q -o "$work/plain.hdr" || fail "render without adaptive sampling"
cmp -s "$work/flags.hdr" "$work/settings.hdr" || fail "flags and scene settings differ"
if cmp -s "$work/flags.hdr" "$work/plain.hdr"; then fail "adaptive sampling changed nothing"; fi
summary=$(grep '^  adaptive ' "$work/log") || fail "the summary has no adaptive line"
case "$summary" in
  *"threshold 0.2, min 8 spp: "*" of 768 pixels stopped ("*" %), mean "*" spp") ;;
  *) fail "unexpected summary line: $summary" ;;
esac
stopped=$(echo "$summary" | sed -n 's/.*spp: \([0-9]*\) of.*/\1/p')
[ "$stopped" -gt 0 ] && [ "$stopped" -lt 768 ] || fail "expected some but not all pixels to stop: $summary"

# Checkpointed at 16 spp (a decision point), resumed to 48: the uninterrupted render's bytes.
"$wavetrace" render "$scene" "${size[@]}" --spp 16 "${adaptive[@]}" -q -o "$work/part16.ckpt" || fail "16 spp"
head -c 2000 "$work/part16.ckpt" | grep -qa '^adaptive_state yes$' || fail "the checkpoint holds no adaptive state"
"$wavetrace" render "$scene" "${size[@]}" --resume "$work/part16.ckpt" --spp 48 "${adaptive[@]}" -q -o "$work/resumed.ckpt" ||
  fail "resume to 48 spp"
cmp -s "$work/resumed.ckpt" "$work/whole.ckpt" || fail "resumed from 16 to 48 spp differs from the 48-spp render"

# expect_refusal SUBSTRING COMMAND...: exit 1, SUBSTRING in the message, no file changed.
expect_refusal() {
  local expected=$1 before output status
  shift
  before=$(cd "$work" && ls -A | sort | xargs -r md5sum)
  output=$("$@" 2>&1)
  status=$?
  [ "$status" -eq 1 ] || fail "exit $status (expected 1) for: $*"$'\n'"$output"
  case "$output" in *"$expected"*) ;; *) fail "expected '$expected' in: $output" ;; esac
  [ "$before" = "$(cd "$work" && ls -A | sort | xargs -r md5sum)" ] || fail "files changed by: $*"
}
expect_refusal "adaptive_threshold: checkpoint 0.200000003, this render 0.100000001" \
  "$wavetrace" render "$scene" "${size[@]}" --resume "$work/part16.ckpt" --spp 48 --adaptive-threshold 0.1 --adaptive-min-spp 8 -q
expect_refusal "adaptive_min_spp: checkpoint 8, this render 16" \
  "$wavetrace" render "$scene" "${size[@]}" --resume "$work/part16.ckpt" --spp 48 --adaptive-threshold 0.2 -q
expect_refusal "adaptive_threshold: checkpoint 0.200000003, this render 0" \
  "$wavetrace" render "$scene" "${size[@]}" --resume "$work/part16.ckpt" --spp 48 -q
expect_refusal "--samples 0:16: a render with adaptive sampling cannot be split into sample ranges" \
  "$wavetrace" render "$scene" "${size[@]}" "${adaptive[@]}" --samples 0:16 -o "$work/split.ckpt"
expect_refusal "is a render with adaptive sampling, which cannot be merged with other parts" \
  "$wavetrace" merge "$work/part16.ckpt" "$work/whole.ckpt" -o "$work/merged.png"
# One adaptive checkpoint alone merges into its image (.hdr files carry no metadata).
"$wavetrace" merge "$work/whole.ckpt" -o "$work/merged.hdr" -q || fail "merge of one adaptive checkpoint"
cmp -s "$work/merged.hdr" "$work/flags.hdr" || fail "the merge of one adaptive checkpoint is not its image"
echo "ok: flags = scene settings, '$summary', 16 -> 48 spp resume byte-identical, refusals named"
