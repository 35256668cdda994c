#!/usr/bin/env bash
# Usage: raw_bytes.sh WAVETRACE SCENE
# Bad values holding raw bytes (an escape sequence, invalid UTF-8) must be reported with the
# bytes escaped as \xNN, never echoed to the terminal.
set -u
wavetrace=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
check() {
  local output
  output=$(cd "$work" && "$@" 2>&1)
  if [ $? -eq 0 ]; then echo "FAIL: exited 0: $*"; status=1; fi
  if printf '%s' "$output" | LC_ALL=C grep -q '[^[:print:][:space:]]'; then
    echo "FAIL: raw bytes in the message of: $*"; printf '%s\n' "$output" | od -c | head; status=1
  fi
  case "$output" in *'\x'*) ;; *) echo "FAIL: no \\xNN escape in: $output"; status=1 ;; esac
}
check "$wavetrace" render "$scene" --spp $'\xff\x1b[31m'
check "$wavetrace" render "$work"/$'\xc3\x28.json'
printf '{"camera": \xff}' > "$work/bad.json"
check "$wavetrace" render "$work/bad.json"
rm -f "$work/bad.json"
[ "$status" -eq 0 ] && echo "ok: every message escaped its raw bytes"
exit "$status"
