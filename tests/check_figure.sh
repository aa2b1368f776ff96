#!/usr/bin/env bash
# Usage: check_figure.sh PENNY SCENE.prm PLOT_SCRIPT OUTPUT_DIR FIGURE.png...
# Runs the scene in a scratch folder, then the plotting script on its output
# folder, and checks that each figure is a non-empty PNG.
set -eu
penny=$1 scene=$2 script=$3 output=$4
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$penny" "$scene" > /dev/null
/usr/bin/python3 "$script" "$output" > /dev/null
for figure in "$@"; do
  [ -s "$output/$figure" ] || { echo "FAIL: $output/$figure missing or empty"; exit 1; }
  [ "$(head -c 8 "$output/$figure" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ] || { echo "FAIL: $figure is not a PNG"; exit 1; }
  echo "ok: $figure, $(stat -c %s "$output/$figure") bytes"
done
