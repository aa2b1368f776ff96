#!/usr/bin/env bash
# Wall time of a sweep scene on 1 and on 2 MPI ranks, the speed-up, and
# whether the results agree: every CSV table, run times and memory aside
# (postprocess/compare_results.py), must be identical, number for number.
# Usage: postprocess/benchmark_sweeps.sh build/penny [SCENE.prm]
# (default: prms/fe-gap-area.prm). Each run writes into a folder of its own
# (the scene's Output/Directory is replaced). Run it on an otherwise idle
# machine: a second rank shares the cores with whatever else runs.
set -euo pipefail
usage="usage: postprocess/benchmark_sweeps.sh build/penny [SCENE.prm]"
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "$usage" >&2; exit 2; }
[ -x "$1" ] || { echo "benchmark_sweeps.sh: '$1' is not an executable penny ($usage)" >&2; exit 2; }
scene=${2:-prms/fe-gap-area.prm}
[ -f "$scene" ] || { echo "benchmark_sweeps.sh: scene file '$scene' does not exist ($usage)" >&2; exit 2; }
penny=$(realpath "$1")
scene=$(realpath "$scene")
compare=$(dirname "$(realpath "$0")")/compare_results.py
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
declare -A seconds
for ranks in 1 2; do
  mkdir "$work/$ranks"
  # The scene with its output in this run's folder (the last setting wins in a prm).
  { grep -v '^ *set Directory *=' "$scene"; printf 'subsection Output\n  set Directory = %s\nend\n' "$work/$ranks/out"; } \
    > "$work/$ranks/scene.prm"
  start=$(date +%s.%N)
  (cd "$work/$ranks" && mpirun -np $ranks "$penny" scene.prm < /dev/null > log 2>&1) || {
    echo "benchmark_sweeps.sh: the run on $ranks rank(s) failed:" >&2
    grep '^penny: ' "$work/$ranks/log" >&2 || tail -5 "$work/$ranks/log" >&2
    exit 1
  }
  seconds[$ranks]=$(echo "$(date +%s.%N) - $start" | bc)
done
identical=no
/usr/bin/python3 "$compare" "$work/1/out" "$work/2/out" 0 > "$work/comparison" && identical=yes
printf "scene %s\n1 rank: %.1f s, 2 ranks: %.1f s, speed-up %.2f; results identical: %s\n" \
  "$(basename "$scene")" "${seconds[1]}" "${seconds[2]}" "$(echo "${seconds[1]} / ${seconds[2]}" | bc -l)" "$identical"
[ $identical = yes ] || cat "$work/comparison"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores)"
[ $identical = yes ]
