#!/usr/bin/env bash
# Instruction-count performance gate. Counts the instructions of fixed workloads with
# valgrind's callgrind (deterministic for a given binary, unlike wall time on a shared
# 2-core machine) and fails when one grows past the baseline by more than TOLERANCE percent,
# or when a SIMD kernel stops beating the scalar one by the stated factor in this same run.
# Each workload also prints a checksum of what it computed (hits, image, tree); it must equal
# the baseline's and be the same for every ISA, so a kernel that does less work cannot pass as
# a faster one.
#
#   bench/perf_gate.sh BUILD_DIR            check against bench/perf_gate_baseline.txt
#   bench/perf_gate.sh BUILD_DIR --update   re-measure and rewrite the baseline (commit it,
#                                           saying in the message why the counts moved)
#
# valgrind 3.19 cannot execute AVX-512, so the gate covers the scalar, SSE4 and AVX2 kernels;
# AVX-512 shares their source (one template) and is checked by bench_intersect ratios.
set -euo pipefail

build_dir=${1:?usage: perf_gate.sh BUILD_DIR [--update]}
mode=${2:-check}
here=$(cd "$(dirname "$0")" && pwd)
baseline=$here/perf_gate_baseline.txt
scene=$here/../scenes/hexroom.json
workload=$build_dir/bin/perf_gate_workload
TOLERANCE=${TOLERANCE:-2}   # percent: callgrind counts move only when code or compiler does

# Loud, never a silent skip: CI installs valgrind (tools/install-deps.sh), so its absence is an error.
command -v valgrind >/dev/null || { echo "perf_gate: FAILED: valgrind is not installed (tools/install-deps.sh installs it)" >&2; exit 1; }
[ -x "$workload" ] || { echo "perf_gate: $workload not built" >&2; exit 1; }

cases=()
for isa in scalar sse4 avx2; do
  for layout in raypacket primpacket bvh bvhpackets bvhinterleaved; do
    for query in closest any; do cases+=("intersect/$isa/$layout/$query"); done
  done
done
cases+=("build" "render/scalar" "render/avx2" "shade/scalar" "shade/sse4" "shade/avx2")
cases+=("shade/scalar/smooth" "shade/sse4/smooth" "shade/avx2/smooth")
cases+=("lightstart/scalar" "lightstart/sse4" "lightstart/avx2" "specular/scalar" "specular/sse4" "specular/avx2")

measure() {  # CASE -> "INSTRUCTIONS CHECKSUM": the collected region's count, the workload's checksum
  local args out count checksum
  IFS=/ read -r -a args <<< "$1"
  out=$(mktemp)
  count=$(valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file=/dev/null \
    "$workload" "$scene" "${args[@]}" 2>&1 >"$out" | awk '/Collected :/ {print $NF}')
  checksum=$(awk '$1 == "checksum" {print $2}' "$out")
  rm -f "$out"
  echo "$count $checksum"
}

declare -A measured checksum
for c in "${cases[@]}"; do
  read -r measured[$c] checksum[$c] < <(measure "$c")
  [ -n "${measured[$c]}" ] || { echo "perf_gate: no count for $c" >&2; exit 1; }
  [ -n "${checksum[$c]}" ] || { echo "perf_gate: no checksum for $c" >&2; exit 1; }
done

if [ "$mode" = "--update" ]; then
  {
    echo "# Instructions counted by bench/perf_gate.sh (callgrind). Regenerate with:"
    echo "#   bench/perf_gate.sh build --update"
    echo "# CASE INSTRUCTIONS CHECKSUM"
    for c in "${cases[@]}"; do echo "$c ${measured[$c]} ${checksum[$c]}"; done
  } > "$baseline"
  echo "perf_gate: wrote $baseline"
  exit 0
fi

failures=0
printf '%-36s %14s %14s %8s\n' case baseline measured change
for c in "${cases[@]}"; do
  base=$(awk -v c="$c" '$1 == c {print $2}' "$baseline")
  base_checksum=$(awk -v c="$c" '$1 == c {print $3}' "$baseline")
  if [ -z "$base" ]; then
    echo "perf_gate: $c missing from $baseline (run with --update)"; failures=$((failures + 1)); continue
  fi
  change=$(awk -v m="${measured[$c]}" -v b="$base" 'BEGIN {printf "%+.2f", 100 * (m - b) / b}')
  verdict=ok
  if awk -v ch="$change" -v tol="$TOLERANCE" 'BEGIN {exit !(ch > tol)}'; then verdict=SLOWER; failures=$((failures + 1)); fi
  if [ "${checksum[$c]}" != "$base_checksum" ]; then
    verdict="$verdict, CHECKSUM ${checksum[$c]} != baseline ${base_checksum:-none}"; failures=$((failures + 1))
  fi
  printf '%-36s %14s %14s %7s%% %s\n' "$c" "$base" "${measured[$c]}" "$change" "$verdict"
done

# Every ISA computes the same bits (the kernels are tested for it): the same checksum per
# workload whatever the ISA, and the BVH's packet and interleaved walks the same as its single-ray one.
same_result() {  # CASE... : all must have the first one's checksum
  local first=$1 c
  for c in "$@"; do
    if [ "${checksum[$c]}" != "${checksum[$first]}" ]; then
      echo "checksum $c ${checksum[$c]} differs from $first ${checksum[$first]}: FAILED"; failures=$((failures + 1))
    fi
  done
}
for query in closest any; do
  for layout in raypacket primpacket; do
    same_result intersect/{scalar,sse4,avx2}/$layout/$query
  done
  same_result intersect/{scalar,sse4,avx2}/{bvh,bvhpackets,bvhinterleaved}/$query
done
same_result render/scalar render/avx2
same_result shade/{scalar,sse4,avx2}
same_result shade/{scalar,sse4,avx2}/smooth
same_result lightstart/{scalar,sse4,avx2}
same_result specular/{scalar,sse4,avx2}

# Ratios within this run: the SIMD kernels must keep their advantage over scalar.
ratio() { awk -v a="${measured[$1]}" -v b="${measured[$2]}" 'BEGIN {printf "%.2f", a / b}'; }
check_ratio() {  # SLOW FAST MIN_FACTOR
  local r; r=$(ratio "$1" "$2")
  local verdict=ok
  if awk -v r="$r" -v m="$3" 'BEGIN {exit !(r < m)}'; then verdict=FAILED; failures=$((failures + 1)); fi
  printf 'ratio %-58s %6sx (at least %sx) %s\n' "$1 / $2" "$r" "$3" "$verdict"
}
check_ratio intersect/scalar/raypacket/closest intersect/avx2/raypacket/closest 4
check_ratio intersect/scalar/raypacket/any intersect/avx2/raypacket/any 3
check_ratio intersect/scalar/raypacket/closest intersect/sse4/raypacket/closest 2
check_ratio render/scalar render/avx2 1.3
check_ratio intersect/scalar/bvh/closest intersect/avx2/bvh/closest 2
check_ratio shade/scalar shade/avx2 4
check_ratio shade/scalar shade/sse4 1.8  # SSE4 has no gather: the surface kernel loads lane by lane
check_ratio shade/scalar/smooth shade/avx2/smooth 4
check_ratio shade/scalar/smooth shade/sse4/smooth 1.8
check_ratio lightstart/scalar lightstart/avx2 4
check_ratio lightstart/scalar lightstart/sse4 2.2
check_ratio specular/scalar specular/avx2 4
check_ratio specular/scalar specular/sse4 2.2

if [ "$failures" -gt 0 ]; then
  echo "perf_gate: $failures check(s) failed. If the change is intended, run bench/perf_gate.sh build --update and commit the baseline."
  exit 1
fi
echo "perf_gate: all checks passed (tolerance ${TOLERANCE}%)"
