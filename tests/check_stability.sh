#!/usr/bin/env bash
# Usage: check_stability.sh PENNY SCENE.prm EXPECTED [MPIRUN...]
# Runs a stability scene (which exits non-zero on any failed case), under
# MPIRUN if given, and checks its stability.csv against EXPECTED: lines
# "COUNT PATTERN", each saying how many rows match the grep pattern (cases
# that pass, and cases designed to miss flagged with their reasons).
set -eu
penny=$(realpath "$1") scene=$(realpath "$2") expected=$(realpath "$3")
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$@" "$penny" "$scene"
table=$(find . -name stability.csv)
[ -n "$table" ] || { echo "FAIL: no stability.csv"; exit 1; }
while read -r count pattern; do
  case "$count" in ''|'#'*) continue ;; esac
  found=$(grep -c -- "$pattern" "$table" || true)
  [ "$found" -eq "$count" ] || { echo "FAIL: $found rows match '$pattern', expected $count"; exit 1; }
done < "$expected"
echo "ok: $(grep -c ',pass$' "$table") pass, $(grep -c flagged "$table") flagged"
