#!/usr/bin/env bash
# Usage: check_ranks.sh PENNY SCENE.prm COMPARE_RESULTS.py
# Runs a scene whose work is spread over the ranks (realisations, the models
# of a search, the searches of a sweep) on 1 and on 2 MPI ranks and checks
# that its tables are identical, number for number, run times and memory
# aside (postprocess/compare_results.py): each piece of work is the same on
# any number of ranks and gathered in the same order.
set -eu
penny=$1 scene=$2 compare=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for ranks in 1 2; do
  # The copy runs here: a relative File starts at the scene's own folder.
  sed -e "s|set Directory *=.*|set Directory = ranks-$ranks|" \
      -e "s|set File *= *\([^/ ].*\)|set File = $(dirname "$scene")/\1|" "$scene" > scene.prm
  mpirun -np $ranks "$penny" scene.prm > ranks-$ranks.log
done
if ! /usr/bin/python3 "$compare" ranks-1 ranks-2 0; then
  echo "FAIL: the tables above differ between 1 and 2 ranks"
  exit 1
fi
