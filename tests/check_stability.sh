#!/usr/bin/env bash
# Usage: check_stability.sh PENNY SCENE.prm EXPECTED [MPIRUN...]
# Runs a stability scene (which exits non-zero on any failed case), under
# MPIRUN if given, and checks what check_scene.sh checks of every scene (no
# message on stderr, the results folder announced), and its stability.csv
# against EXPECTED: lines "COUNT PATTERN", each saying how many rows match the
# grep pattern (cases that pass, and cases designed to miss flagged with their
# reasons). The scene's test-size file has this test instead of scene_NAME.
set -eu
penny=$(realpath "$1") scene=$(realpath "$2") expected=$(realpath "$3")
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$@" "$penny" "$scene" > stdout 2> stderr || { echo "FAIL: exit status $?"; cat stdout stderr; exit 1; }
cat stdout
[ ! -s stderr ] || { echo "FAIL: messages on stderr"; cat stderr; exit 1; }
grep -q "^Results in " stdout || { echo "FAIL: no results folder announced"; exit 1; }
table=$(find . -name stability.csv)
[ -n "$table" ] || { echo "FAIL: no stability.csv"; exit 1; }
while read -r count pattern; do
  case "$count" in ''|'#'*) continue ;; esac
  found=$(grep -c -- "$pattern" "$table" || true)
  [ "$found" -eq "$count" ] || { echo "FAIL: $found rows match '$pattern', expected $count"; exit 1; }
done < "$expected"
echo "ok: $(grep -c ',pass$' "$table") pass, $(grep -c flagged "$table") flagged"
