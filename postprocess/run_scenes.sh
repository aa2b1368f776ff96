#!/usr/bin/env bash
# Runs parameter files with one penny binary, each in a folder of its own, so
# that two builds can be compared table by table:
#   postprocess/run_scenes.sh build/penny before tests/scenes/*.prm
#   (rebuild)
#   postprocess/run_scenes.sh build/penny after tests/scenes/*.prm
#   /usr/bin/python3 postprocess/compare_results.py before after
# OUT/NAME/ receives the results (relative output folders land there) and
# OUT/NAME/log.txt the screen output; the exit status of each run is printed.
set -u
[ $# -ge 3 ] || { echo "usage: $0 PENNY OUT PRM..." >&2; exit 2; }
penny=$(realpath "$1") out=$2
shift 2
[ -x "$penny" ] || { echo "$0: $penny is not an executable" >&2; exit 2; }
failed=0
for prm in "$@"; do
  name=$(basename "$prm" .prm) file=$(realpath "$prm")
  mkdir -p "$out/$name" || exit 2
  start=$(date +%s.%N)
  (cd "$out/$name" && "$penny" "$file" > log.txt 2>&1)
  status=$?
  printf '%-28s exit %d  %6.1f s\n' "$name" "$status" "$(echo "$(date +%s.%N) - $start" | bc)"
  [ $status -eq 0 ] || failed=1
done
exit $failed
