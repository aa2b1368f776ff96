#!/usr/bin/env bash
# Usage: bad_input.sh PENNY PRM EXPECTED
# Runs PENNY on the bad parameter file PRM in a scratch folder holding an
# earlier result in out/ (the folder the bad files name), and checks: non-zero
# exit, exactly one short line on stderr containing EXPECTED, the earlier
# result intact.
set -u
penny=$1 prm=$2 expected=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/out"
echo "earlier result" > "$work/out/rings.csv"
touch "$work/out/.penny-results"
cd "$work" || exit 1

"$penny" "$prm" > stdout 2> stderr
status=$?
fail() { echo "FAIL: $*"; echo "--- stderr:"; cat stderr; exit 1; }
[ "$status" -ne 0 ] || fail "exit status 0"
[ "$(wc -l < stderr)" -eq 1 ] || fail "stderr is not one line"
[ "$(wc -c < stderr)" -le 600 ] || fail "stderr is longer than 600 characters"
grep -qF -- "$expected" stderr || fail "stderr lacks: $expected"
[ "$(cat out/rings.csv)" = "earlier result" ] || fail "the earlier result in out/ was changed"
[ -z "$(ls out | grep -v '^rings.csv$')" ] || fail "the failed run wrote into out/"
[ -z "$(ls -A . | grep staging)" ] || fail "the failed run left a staging folder"
echo "ok: $(cat stderr)"
