#!/usr/bin/env bash
# Usage: check_scene_list.sh PENNY TESTS/SCENES
# Every registered scene has a test-size parameter file of its own name that
# selects it, so that adding a scene adds its test (each file there is run by
# check_scene.sh, or check_stability.sh where it has an .expect file).
set -u
penny=$1 folder=$2
scenes=$("$penny" --help | sed -n '/Scenes:$/,$p' | awk 'NR > 1 {print $1}')
[ -n "$scenes" ] || { echo "FAIL: no scenes listed by penny --help"; exit 1; }
missing=0
for scene in $scenes; do
  prm=$folder/$scene.prm
  if ! grep -q "^set Scene *= *$scene *$" "$prm" 2> /dev/null; then
    echo "FAIL: scene $scene has no $prm that selects it"
    missing=1
  fi
done
[ $missing -eq 0 ] && echo "ok: $(echo $scenes | wc -w) scenes, each with its test-size file"
exit $missing
