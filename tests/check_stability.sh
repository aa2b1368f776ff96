#!/usr/bin/env bash
# Usage: check_stability.sh PENNY SCENE.prm
# Runs the stability scene (which exits non-zero on any failed case) and checks
# that the cases designed to miss the target are flagged with their reasons.
set -eu
penny=$1 scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$penny" "$scene"
table=stability/stability.csv
expect() { # expect COUNT PATTERN
  found=$(grep -c -- "$2" "$table" || true)
  [ "$found" -eq "$1" ] || { echo "FAIL: $found rows match '$2', expected $1"; exit 1; }
}
expect 0 'FAIL'
expect 5 'flagged: degree-1 elements lock'
expect 5 '^incompressibility,"degree 4.*,pass$'
expect 4 '^scales,.*,pass$'
expect 1 'a/c = 0.5,.*flagged: K_I < 0: the faces would interpenetrate'
expect 2 'c/R = c/H = 0.*flagged: finite domain'
expect 2 '^near the root,.*,pass$'
expect 2 '^solvers,.*,pass$'
echo "ok: $(grep -c pass "$table") pass, $(grep -c flagged "$table") flagged"
