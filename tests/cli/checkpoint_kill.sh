#!/usr/bin/env bash
# Usage: checkpoint_kill.sh WAVETRACE SCENE
# SIGKILL while a checkpoint is being written (its temporary file exists) leaves the previous
# checkpoint whole: it still reads, and a resume from it finishes the render. The test waits
# for the render's own "checkpoint" line and then for the temporary to appear, never for a
# fixed time.
source "$(dirname "$0")/script_setup.sh"

# 1200x900 pixels make a checkpoint of about 56 MB, a write long enough to be caught in.
mkfifo "$work/fifo"
"$wavetrace" render "$scene" --width 1200 --height 900 --spp 1000 --threads 2 --checkpoint "$work/c.ckpt" \
  --checkpoint-every 0.001 -o "$work/out.png" >/dev/null 2>"$work/fifo" &
pid=$!
exec 3<"$work/fifo"
while IFS= read -r line <&3; do
  echo "$line" >>"$work/log"
  case "$line" in *"wavetrace: checkpoint "*) break ;; esac
done
[ -s "$work/c.ckpt" ] || fail "no first checkpoint"
cat <&3 >>"$work/log" &
drain=$!
# The next checkpoint's temporary (.c.tmp-PID.ckpt beside the target), once it has some bytes.
temporary="$work/.c.tmp-$pid.ckpt"
while [ ! -s "$temporary" ]; do
  kill -0 "$pid" 2>/dev/null || fail "the render ended before writing a second checkpoint"
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null
status=$?
wait "$drain"
exec 3<&-
[ "$status" -eq 137 ] || fail "exit $status after SIGKILL, expected 137"
[ -e "$temporary" ] || fail "the kill did not come while the temporary existed"
"$wavetrace" merge "$work/c.ckpt" -o "$work/check.ckpt" -q || fail "the previous checkpoint no longer reads"
held=$(sed -n 's/^samples 0 \([0-9]*\) 1000$/\1/p' "$work/check.ckpt" | head -n 1)
[ -n "$held" ] || fail "no sample range in the checkpoint"
"$wavetrace" render "$scene" --width 1200 --height 900 --threads 2 --resume "$work/c.ckpt" --spp $((held + 1)) -q \
  -o "$work/resumed.png" || fail "resume from the checkpoint that survived"
echo "ok: SIGKILL during a checkpoint write ($(stat -c %s "$temporary") bytes of the temporary written) left the previous one ($held spp) valid and resumable"
