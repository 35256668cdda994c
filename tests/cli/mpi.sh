#!/usr/bin/env bash
# Usage: mpi.sh WAVETRACE_MPI SCENE
# The render spread over MPI ranks (a build with -DWAVETRACE_MPI=ON): 2 and 3 ranks on this
# machine give the bits of one process and of `merge` of a --samples split; a rank killed
# during the render fails the run with a message, and no image is written.
source "$(dirname "$0")/script_setup.sh"
# Root (CI containers) needs OpenMPI's explicit consent.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
size=(--width 48 --height 36 --spp 24 --threads 1)

"$wavetrace" render "$scene" "${size[@]}" -q -o "$work/one.ckpt" || fail "one process"
"${mpirun[@]}" -np 2 "$wavetrace" render "$scene" "${size[@]}" -q -o "$work/np2.ckpt" -o "$work/np2.png" || fail "-np 2"
"${mpirun[@]}" -np 3 "$wavetrace" render "$scene" "${size[@]}" -q -o "$work/np3.ckpt" || fail "-np 3"
for range in 0:7 7:8 8:24; do
  "$wavetrace" render "$scene" "${size[@]}" -q --samples "$range" -o "$work/part-$range.ckpt" || fail "--samples $range"
done
"$wavetrace" merge "$work"/part-*.ckpt -q -o "$work/merged.ckpt" || fail "merge"
cmp -s "$work/np2.ckpt" "$work/np3.ckpt" || fail "-np 2 and -np 3 differ"
cmp -s "$work/np2.ckpt" "$work/one.ckpt" || fail "-np 2 differs from one process"
cmp -s "$work/np2.ckpt" "$work/merged.ckpt" || fail "-np 2 differs from the merged split"
[ -s "$work/np2.png" ] || fail "-np 2 wrote no image"

# Kill rank 1 after the first chunk is done: its pid is in its start-up line.
"${mpirun[@]}" -np 2 "$wavetrace" render "$scene" --width 200 --height 150 --spp 512 --threads 1 -o "$work/dead.png" \
  >"$work/log" 2>&1 &
job=$!
pid=""
while [ -z "$pid" ]; do
  kill -0 "$job" 2>/dev/null || fail "the job ended before rank 1 started"
  pid=$(sed -n 's/.*MPI rank 1 of 2 on .*, pid \([0-9]*\),.*/\1/p' "$work/log")
done
until grep -q "rendered samples" "$work/log"; do
  kill -0 "$job" 2>/dev/null || fail "the job ended before a chunk was done"
done
kill -KILL "$pid"
wait "$job"
status=$?
[ "$status" -ne 0 ] || fail "the job with a killed rank exited 0"
grep -q "rank 1" "$work/log" && grep -qi "killed\|exited on signal" "$work/log" || fail "no message about the dead rank"
[ ! -e "$work/dead.png" ] || fail "an image was written without rank 1's samples"
echo "ok: -np 2, -np 3, one process and merge of 0:7 7:8 8:24 give the same bits; a killed rank fails the job (exit $status) with no image"
