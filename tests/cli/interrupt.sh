#!/usr/bin/env bash
# Usage: interrupt.sh WAVETRACE SCENE
# Ctrl-C during a render, as a user does it: the first SIGINT ends the render at the next pass
# boundary, writes the image and exits 3; two SIGINTs exit at once (130) and leave the image
# that was already there untouched and no temporary file. The test waits for the render's own
# "pass 1 done" line on stderr (through a FIFO), never for a fixed time.
source "$(dirname "$0")/script_setup.sh"

# Starts a long render whose stderr goes through a FIFO. A pass of one sample of 640x480
# takes a good part of a second, long enough for a second signal to arrive during it.
start_render() {
  rm -f "$work/fifo"
  mkfifo "$work/fifo"
  "$wavetrace" render "$scene" --width 640 --height 480 --spp 1000000 --threads 2 -o "$work/out.png" \
    >"$work/stdout" 2>"$work/fifo" &
  pid=$!
  exec 3<"$work/fifo"
}
# Reads the render's stderr until a line contains $1.
wait_for() {
  while IFS= read -r line <&3; do
    echo "$line" >>"$work/log"
    case "$line" in *"$1"*) return 0 ;; esac
  done
  fail "stderr ended before '$1'"
}
# Keeps draining stderr, so the render never blocks writing to it.
drain() {
  cat <&3 >>"$work/log" &
  drain=$!
}
# Sends the last SIGINT, waits for the render to exit and sets $status to its exit status.
interrupt_and_wait() {
  kill -INT "$pid"
  wait "$pid"
  status=$?
  wait "$drain"
  exec 3<&-
}

# One SIGINT: stops at a pass boundary, writes the image, exit 3.
start_render
wait_for "pass 1 done"
drain
interrupt_and_wait
[ "$status" -eq 3 ] || fail "one SIGINT: exit $status, expected 3"
[ -s "$work/out.png" ] || fail "one SIGINT: no image written"
grep -q "interrupted" "$work/stdout" || fail "one SIGINT: the summary does not say interrupted"
spp=$(sed -n 's/.*, \([0-9]*\) spp,.*/\1/p' "$work/stdout" | head -n 1)
[ -n "$spp" ] && [ "$spp" -ge 1 ] && [ "$spp" -lt 1000000 ] || fail "one SIGINT: summary spp '$spp'"

# Two SIGINTs: exit at once with 128 + SIGINT, the earlier image intact, no temporary left.
cp "$work/out.png" "$work/before.png"
start_render
wait_for "pass 1 done"
kill -INT "$pid"
wait_for "interrupted:"  # signals do not queue: the second must come after the first was taken
drain
interrupt_and_wait
[ "$status" -eq 130 ] || fail "two SIGINTs: exit $status, expected 130"
cmp -s "$work/out.png" "$work/before.png" || fail "two SIGINTs: the existing image changed"
leftover=$(ls -A "$work" | grep -v -x -e out.png -e before.png -e fifo -e log -e stdout)
[ -z "$leftover" ] || fail "two SIGINTs: files left behind: $leftover"
echo "ok: one SIGINT exits 3 at $spp spp with the image written; two exit 130 leaving files intact"
