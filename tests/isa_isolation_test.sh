#!/usr/bin/env bash
# Usage: isa_isolation_test.sh BINARY...
# Code compiled for an instruction set must stay inside the translation unit compiled for it
# (cmake/isa_object.cmake). Disassembles each binary and fails if
#   - a function using AVX-512 (zmm, mask registers k1-k7, xmm16-31/ymm16-31, EVEX-only
#     instructions) is neither in an AVX-512 TU nor in our wt::...::isa_avx512 namespace,
#   - a function using 256-bit ymm registers is in neither an AVX2 nor an AVX-512 TU nor in the
#     isa_avx2 / isa_avx512 namespaces,
#   - a static initialiser (run at start-up on every CPU) uses AVX-512 anywhere.
# A local function belongs to the TU named by the FILE symbol before it in the symbol table.
set -euo pipefail
status=0
# The address -> TU table goes to awk as a file: as an argument (-v) a sanitizer build's table
# passes the kernel's 128 kB limit on one argument ("Argument list too long").
files=$(mktemp)
trap 'rm -f "$files"' EXIT
for binary in "$@"; do
  # address -> TU source file, for local functions; "" for global ones.
  readelf -sW "$binary" | awk '
    $4 == "FILE" { file = $8; next }
    $4 == "FUNC" && $5 == "LOCAL" { print $2, file; next }
    $4 == "FUNC" { print $2, "" }' >"$files"
  report=$(objdump -d --no-show-raw-insn -C "$binary" | awk '
    FNR == NR { addr = $1; sub(/^0+/, "", addr); file_of[addr] = $2; next }
    function finish() {
      if (name == "") return
      file = file_of[addr]
      in512 = file ~ /avx512/ || name ~ /isa_avx512/
      in256 = in512 || file ~ /avx2/ || name ~ /isa_avx2/
      if (avx512 && !in512) print "AVX-512 outside AVX-512 code: " name " (" (file == "" ? "global" : file) ")"
      if (ymm && !in256) print "AVX2 (ymm) outside AVX2/AVX-512 code: " name " (" (file == "" ? "global" : file) ")"
      if (avx512 && name ~ /_GLOBAL__sub_I|static_initialization/) print "AVX-512 in a static initialiser: " name " (" file ")"
      checked++
    }
    /^[0-9a-f]+ <.*>:$/ {
      finish()
      addr = $1; sub(/^0+/, "", addr)
      name = $0; sub(/^[0-9a-f]+ </, "", name); sub(/>:$/, "", name)
      avx512 = 0; ymm = 0
      next
    }
    /%zmm|%k[1-7]|%[xy]mm(1[6-9]|2[0-9]|3[01])|\{1to|vpternlog|vpermt2|vmovdq[au](8|16|32|64)|vpcmp[a-z]*\s.*%k/ { avx512 = 1 }
    /%ymm/ { ymm = 1 }
    END { finish(); print "checked " checked " functions" > "/dev/stderr" }' "$files" -)
  if [ -n "$report" ]; then
    echo "FAIL: $binary:"; echo "$report" | head -20; status=1
  else
    echo "ok: $binary"
  fi
done
exit "$status"
