#!/usr/bin/env bash
# Usage: expect_error.sh EXPECTED_SUBSTRING COMMAND [ARGS...]
# Passes when COMMAND exits non-zero, its output names the problem (contains EXPECTED_SUBSTRING),
# and it leaves no image behind in its working directory.
set -u
expected=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
output=$(cd "$work" && "$@" 2>&1)
status=$?
if [ "$status" -eq 0 ]; then
  echo "FAIL: exited 0, expected an error mentioning: $expected"; echo "$output"; exit 1
fi
if [ "$status" -ge 128 ]; then
  echo "FAIL: killed by signal $((status - 128)) (a crash, not an error message)"; echo "$output"; exit 1
fi
case "$output" in
  *"$expected"*) ;;
  *) echo "FAIL: output does not mention: $expected"; echo "$output"; exit 1 ;;
esac
if [ -n "$(ls -A "$work")" ]; then
  echo "FAIL: left files behind:"; ls -la "$work"; exit 1
fi
echo "ok: exit $status, message: $(echo "$output" | head -n 1)"
