#!/usr/bin/env bash
# Usage: layers_test.sh CHECK_LAYERS FIXTURES
# The layer check on two small trees: one whose includes run only downwards (it must pass and
# print its edge), one with an include that runs back up, a folder LAYERS does not place and a
# quoted include of no file (it must fail and name each as FILE:LINE).
set -uo pipefail
check=$1 fixtures=$2
fail() { echo "FAIL: $*"; echo "reproduce: python3 $check --root <fixture> --list"; exit 1; }

out=$(python3 "$check" --root "$fixtures/in_order" --list 2>&1) || fail "in_order was refused: $out"
grep -q -- '-> src/core/base  \[1\]' <<<"$out" || fail "in_order's edge scene -> base not listed: $out"

out=$(python3 "$check" --root "$fixtures/back_edge" 2>&1) && fail "back_edge passed: $out"
grep -q 'src/core/base/ray.h:3: includes src/core/scene/scene.h, but src/core/scene is above src/core/base' <<<"$out" ||
  fail "the upward include is not named at its line: $out"
grep -q 'src/core/unplaced/thing.h: its folder src/core/unplaced has no place in LAYERS' <<<"$out" ||
  fail "the unplaced folder is not named: $out"
grep -q 'src/core/base/ray.h:4: "core/base/missing.h" is no file' <<<"$out" || fail "the include of no file is not named: $out"
# The downward include in back_edge's scene.h is not reported.
grep -q 'scene/scene.h:' <<<"$out" && fail "a downward include was reported: $out"
echo "ok"
