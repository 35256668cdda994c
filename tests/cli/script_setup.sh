# Sourced by the command-line test scripts called as SCRIPT WAVETRACE SCENE: sets $wavetrace,
# $scene and a temporary $work directory removed on exit, and fail(), which prints its
# message and the render's log ($work/log, if the script keeps one) and exits 1.
set -u
wavetrace=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; [ -f "$work/log" ] && cat "$work/log"; exit 1; }
