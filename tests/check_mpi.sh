#!/usr/bin/env bash
# Usage: check_mpi.sh PENNY SCENE.prm SOLVER
# Runs a penny-gap scene on 1 and on 2 MPI ranks with Linear solver/Type = SOLVER
# and checks that K_I agrees on every ring to 1e-10 relative, and that the
# parallel run wrote its VTU pieces and PVD record.
set -eu
penny=$1 scene=$2 solver=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
for ranks in 1 2; do
  sed "s|set Directory *= mpi|set Directory = ranks-$ranks|" "$scene" > scene.prm
  printf 'subsection Linear solver\n  set Type = %s\n  set Tolerance = 1e-12\nend\n' "$solver" >> scene.prm
  mpirun -np $ranks "$penny" scene.prm > ranks-$ranks.log
done
grep -q "MPI ranks *2" ranks-2.log || { echo "FAIL: the 2-rank run does not report 2 ranks"; exit 1; }
ls ranks-2/*.pvd > /dev/null || { echo "FAIL: no PVD record from the 2-rank run"; exit 1; }
/usr/bin/python3 - ranks-1/rings.csv ranks-2/rings.csv <<'PY'
import csv, sys
one, two = ([row for row in csv.DictReader(open(name))] for name in sys.argv[1:3])
assert len(one) == len(two) > 0, "ring tables differ in length"
worst = 0
for a, b in zip(one, two):
    for key in a:
        if "FE" in key:
            worst = max(worst, abs(float(b[key]) / float(a[key]) - 1))
print(f"largest relative K_I difference, 1 vs 2 ranks: {worst:.2e}")
sys.exit(0 if worst <= 1e-10 else 1)
PY
