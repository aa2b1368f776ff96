#!/usr/bin/env bash
# Usage: check_verdict.sh PENNY SCENE.prm (a scene with a Verification/Tolerance entry)
# A penny-gap scene held to a tolerance it cannot meet: it must print FAIL with
# the error and the tolerance on one line of stderr, exit with status 1, and
# still write its results (a verdict is not an error). With the tolerance it
# meets it must print PASS and exit 0.
set -u
penny=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat stderr; exit 1; }
sed 's/set Tolerance = .*/set Tolerance = 1e-12/' "$scene" > strict.prm
"$penny" strict.prm > stdout 2> stderr
[ $? -eq 1 ] || fail "a missed tolerance did not exit with status 1"
[ "$(wc -l < stderr)" -eq 1 ] && grep -q "FAIL: .* > Verification/Tolerance = 1.00e-12" stderr || fail "no one-line FAIL"
[ -s fields/rings.csv ] || fail "a failed verdict did not write its results"
sed 's/set Tolerance = .*/set Tolerance = 0.1/' "$scene" > loose.prm
"$penny" loose.prm > stdout 2> stderr || fail "a met tolerance did not exit 0"
grep -q "^PASS: " stdout || fail "no PASS line"
grep -q "^penny: scene penny-gap" stdout || fail "the scene is not named"
echo "ok: FAIL and PASS verdicts"
