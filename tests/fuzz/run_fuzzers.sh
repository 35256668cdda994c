#!/usr/bin/env bash
# Usage: tests/fuzz/run_fuzzers.sh BUILD_DIR SECONDS [TARGET...]
# Runs each libFuzzer target (default: all of tests/fuzz/CMakeLists.txt's) for SECONDS from its
# seed corpus (tests/fuzz/corpus/TARGET, read only) and its dictionary (tests/fuzz/TARGET.dict),
# keeping what it finds in BUILD_DIR/fuzz-corpus/TARGET. Fails if any target crashes, leaks,
# times out (10 s on one input) or runs out of memory (2 GB); the input that did it is left in
# BUILD_DIR/fuzz-artifacts/ and its path printed: turn it into a test.
# Prints, per target: runs, coverage (edges), corpus size and findings.
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
failed=0
summary=()
for target in "${targets[@]}"; do
  binary=$build_dir/bin/$target
  [ -x "$binary" ] || { echo "run_fuzzers: $binary not built" >&2; exit 1; }
  corpus=$build_dir/fuzz-corpus/$target
  mkdir -p "$corpus"
  dict=()
  [ -f "$here/$target.dict" ] && dict=(-dict="$here/$target.dict")
  log=$build_dir/fuzz-$target.log
  # Run in a scratch directory: inputs may name relative files.
  scratch=$(mktemp -d)
  (cd "$scratch" && "$binary" "${dict[@]}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -malloc_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/$target-" \
      "$corpus" "$here/corpus/$target") > "$log" 2>&1
  status=$?
  rm -rf "$scratch"
  runs=$(awk '/stat::number_of_executed_units/ {print $2}' "$log")
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | awk '{print $2}')
  files=$(find "$corpus" -type f | wc -l)
  findings=$(find "$artifacts" -name "$target-*" -type f | wc -l)
  line=$(printf '%-11s %9s runs  %6s edges  %5s corpus files  %s findings  exit %s' "$target" "${runs:-?}" "${coverage:-?}" "$files" "$findings" "$status")
  summary+=("$line")
  echo "$line"
  if [ "$status" -ne 0 ]; then
    failed=1
    echo "run_fuzzers: $target FAILED; its log: $log"
    grep -E "ERROR|SUMMARY|Test unit written|==[0-9]+==" "$log" | head -20
  fi
done
echo "---"
printf '%s\n' "${summary[@]}"
exit "$failed"
