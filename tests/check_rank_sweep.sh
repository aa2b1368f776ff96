#!/usr/bin/env bash
# Usage: check_rank_sweep.sh PENNY SCENE.prm TABLE.csv...
# Runs a sweep scene on 1 and on 2 MPI ranks (each rank its share of the
# searches, models on one rank each) and checks that the tables are identical,
# byte for byte.
set -euo pipefail
penny=$1 scene=$2
shift 2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ranks in 1 2; do
  mkdir "$work/$ranks"
  sed "s|^\( *set Directory *=\).*|\1 $work/$ranks/out|" "$scene" > "$work/$ranks/scene.prm"
  timeout 600 mpirun -np $ranks "$penny" "$work/$ranks/scene.prm" > "$work/$ranks/log" 2>&1 ||
    { echo "FAIL: the run on $ranks rank(s) failed"; tail -5 "$work/$ranks/log"; exit 1; }
done
for table in "$@"; do
  cmp "$work/1/out/$table" "$work/2/out/$table" || { echo "FAIL: $table differs between 1 and 2 ranks"; exit 1; }
done
grep -h "FE solves" "$work"/*/log
echo "PASS: $* identical on 1 and 2 ranks"
