#!/usr/bin/env bash
# Usage: check_scene.sh PENNY SCENE.prm
# A test-size parameter file runs to completion: exit 0, no message on stderr,
# its results folder announced, and PASS when the scene has a verdict.
set -u
penny=$1 prm=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat stdout stderr; exit 1; }
"$penny" "$prm" > stdout 2> stderr || fail "exit status $?"
[ ! -s stderr ] || fail "messages on stderr"
grep -q "^Results in " stdout || fail "no results folder announced"
if "$penny" --print-parameters "$(sed -n 's/^set Scene *= *//p' "$prm")" | grep -q "^subsection Verification"; then
  grep -q "^PASS: " stdout || fail "a scene with a verdict printed no PASS"
fi
echo "ok: $(basename "$prm") ran to its results"
