#!/usr/bin/env bash
# Usage: resume.sh WAVETRACE SCENE
# A render interrupted by SIGINT at a random pass, then resumed, is bit-identical to one that
# was never interrupted; so is one resumed with a larger --spp, against a render of that spp
# (with the default sampler and with Sobol'). The films are compared through their
# checkpoints (-o X.ckpt), byte for byte. The test waits for the render's own "pass N done"
# lines on stderr (through a FIFO), never for a fixed time.
source "$(dirname "$0")/script_setup.sh"
size=(--width 96 --height 72 --threads 2)

# Renders "$@" with stderr through a FIFO, sends SIGINT after pass $1 and expects exit 3.
interrupt_after_pass() {
  local pass=$1
  shift
  rm -f "$work/fifo"
  mkfifo "$work/fifo"
  "$wavetrace" render "$scene" "${size[@]}" "$@" >"$work/stdout" 2>"$work/fifo" &
  local pid=$!
  exec 3<"$work/fifo"
  local seen=0
  while IFS= read -r line <&3; do
    echo "$line" >>"$work/log"
    case "$line" in *"pass $pass done"*) seen=1; break ;; esac
  done
  [ "$seen" -eq 1 ] || fail "stderr ended before pass $pass"
  cat <&3 >>"$work/log" &
  local drain=$!
  kill -INT "$pid"
  wait "$pid"
  local status=$?
  wait "$drain"
  exec 3<&-
  [ "$status" -eq 3 ] || fail "interrupted after pass $pass: exit $status, expected 3 (did it finish first?)"
}

# Passes of 1, 1, 2, 4, 8 ... spp: stopping after pass 1 to 5 (at most 16 spp) leaves most of 64 to do.
pass=$((RANDOM % 5 + 1))
"$wavetrace" render "$scene" "${size[@]}" --spp 64 -q -o "$work/whole.ckpt" || fail "uninterrupted render"
interrupt_after_pass "$pass" --spp 64 --checkpoint "$work/c.ckpt" -o "$work/stopped.png"
[ -s "$work/c.ckpt" ] || fail "no checkpoint after the interrupt"
held=$(sed -n 's/.*, \([0-9]*\) spp,.*/\1/p' "$work/stdout" | head -n 1)
[ -n "$held" ] && [ "$held" -lt 64 ] || fail "the interrupted render claims '$held' spp"
"$wavetrace" render "$scene" "${size[@]}" --resume "$work/c.ckpt" -q -o "$work/resumed.ckpt" || fail "resume"
cmp -s "$work/resumed.ckpt" "$work/whole.ckpt" || fail "resumed after $held spp (pass $pass) differs from the uninterrupted render"
# The resume updated its checkpoint to the finished render: resuming that again adds nothing.
cmp -s "$work/c.ckpt" "$work/whole.ckpt" || fail "the resumed checkpoint was not brought up to date"

# Interrupted at a 16-spp target (after pass 1 to 3: at most 4 spp, two passes left), resumed to 64 spp: the 64-spp render.
pass2=$((RANDOM % 3 + 1))
interrupt_after_pass "$pass2" --spp 16 --checkpoint "$work/d.ckpt" -o "$work/stopped.png"
"$wavetrace" render "$scene" "${size[@]}" --resume "$work/d.ckpt" --spp 64 -q -o "$work/raised.ckpt" || fail "resume with --spp 64"
cmp -s "$work/raised.ckpt" "$work/whole.ckpt" || fail "resumed from a 16-spp target to 64 spp differs from the 64-spp render"
# The same with the Sobol' sampler, from a finished 8-spp render to 24.
sobol=(--sampler sobol --light-sampling mis)
"$wavetrace" render "$scene" "${size[@]}" "${sobol[@]}" --spp 8 -q -o "$work/sobol8.ckpt" || fail "sobol 8 spp"
"$wavetrace" render "$scene" "${size[@]}" "${sobol[@]}" --resume "$work/sobol8.ckpt" --spp 24 -q -o "$work/sobol_raised.ckpt" ||
  fail "sobol resume to 24 spp"
"$wavetrace" render "$scene" "${size[@]}" "${sobol[@]}" --spp 24 -q -o "$work/sobol24.ckpt" || fail "sobol 24 spp"
cmp -s "$work/sobol_raised.ckpt" "$work/sobol24.ckpt" || fail "sobol: resumed from 8 to 24 spp differs from a 24-spp render"
echo "ok: interrupted after pass $pass ($held spp) and resumed: the uninterrupted bits; after pass $pass2 of 16 spp, resumed to 64: the 64-spp bits; Sobol' 8 -> 24 spp: the 24-spp bits"
