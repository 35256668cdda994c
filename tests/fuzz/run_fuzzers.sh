#!/usr/bin/env bash
# Usage: tests/fuzz/run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]
# Runs each libFuzzer target (default: all of tests/fuzz/CMakeLists.txt's) for SECONDS from its
# seed corpus (tests/fuzz/corpus/TARGET, read only) and its dictionary (tests/fuzz/TARGET.dict),
# keeping what it finds in BUILD_DIR/fuzz-corpus/TARGET. Fails if any target crashes, leaks,
# times out (10 s on one input) or runs out of memory (2 GB); the input that did it is left in
# BUILD_DIR/fuzz-artifacts/ and its path printed: turn it into a test.
# Prints, per target: runs, coverage (edges), corpus size and findings.
# FUZZ_JOBS targets run at once (default: one per core): each libFuzzer process is one thread,
# so on 2 cores the run takes half the wall time for the same fuzzing per target.
set -uo pipefail
build_dir=$(cd "${1:?usage: run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]}" && pwd)
seconds=${2:?usage: run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]}
shift 2
here=$(cd "$(dirname "$0")" && pwd)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_scene fuzz_cli fuzz_obj fuzz_ply fuzz_gltf fuzz_checkpoint)
artifacts=$build_dir/fuzz-artifacts
mkdir -p "$artifacts"
# Leaks are findings; an allocation over the RSS limit is an out-of-memory finding.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
jobs=${FUZZ_JOBS:-$(nproc)}
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

run_target() {  # TARGET: fuzzes it, leaves its summary line in $results/TARGET.line
  local target=$1
  local binary=$build_dir/bin/$target corpus=$build_dir/fuzz-corpus/$target log=$build_dir/fuzz-$target.log
  mkdir -p "$corpus"
  local dict=()
  [ -f "$here/$target.dict" ] && dict=(-dict="$here/$target.dict")
  # fuzz_obj and fuzz_gltf read images through OpenImageIO, whose PNG reader leaks on a
  # truncated file (tests/lsan.supp says where); the suppression needs the slow unwinder to see
  # its frame, which makes those two targets run fewer inputs in their time.
  local lsan=${LSAN_OPTIONS:-}
  case $target in
    fuzz_obj | fuzz_gltf) lsan=${LSAN_OPTIONS:-suppressions=$here/../lsan.supp:fast_unwind_on_malloc=0} ;;
  esac
  # Run in a scratch directory: inputs may name relative files. Its TMPDIR too, so the files a
  # fuzzer writes (FuzzDirectory) go when the scratch directory does, even after a crash.
  local scratch status
  scratch=$(mktemp -d)
  (cd "$scratch" && TMPDIR=$scratch LSAN_OPTIONS=$lsan "$binary" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/$target-" \
      "$corpus" "$here/corpus/$target") > "$log" 2>&1
  status=$?
  rm -rf "$scratch"
  local runs coverage files findings
  runs=$(awk '/stat::number_of_executed_units/ {print $2}' "$log")
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | awk '{print $2}')
  files=$(find "$corpus" -type f | wc -l)
  findings=$(find "$artifacts" -name "$target-*" -type f | wc -l)
  printf '%-15s %9s runs  %6s edges  %5s corpus files  %s findings  exit %s\n' "$target" "${runs:-?}" \
    "${coverage:-?}" "$files" "$findings" "$status" > "$results/$target.line"
  echo "$status" > "$results/$target.status"
}

for target in "${targets[@]}"; do
  [ -x "$build_dir/bin/$target" ] || { echo "run_fuzzers: $build_dir/bin/$target not built" >&2; exit 1; }
done
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  run_target "$target" &
done
wait

failed=0
for target in "${targets[@]}"; do
  cat "$results/$target.line"
  if [ "$(cat "$results/$target.status")" -ne 0 ]; then
    failed=1
    echo "run_fuzzers: $target FAILED; its log: $build_dir/fuzz-$target.log"
    # The stack too: CI keeps only this output, and a SUMMARY line alone names no function.
    grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==|^ +#[0-9]+ |READ of|WRITE of|allocated by|located" \
      "$build_dir/fuzz-$target.log" | head -60
    # The input itself, in base64, so it can be reproduced from CI's output alone.
    for crash in "$artifacts/$target"-*; do
      [ -f "$crash" ] || continue
      echo "run_fuzzers: $crash ($(wc -c < "$crash") bytes), base64:"
      head -c 16384 "$crash" | base64 -w 0; echo
    done
  fi
done
exit "$failed"
