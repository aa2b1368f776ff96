#!/usr/bin/env bash
# Runs every convergence sequence (Release build expected in build/), draws
# error against DoFs and against wall time, and reruns the largest sequences on
# 2 MPI ranks for the speed-up. Usage, from the repository root:
#   postprocess/run_convergence_benchmark.sh
set -euo pipefail
cd "$(dirname "$0")/.."
for sequence in uniform-h tip-grading degree domain-size adaptive uniform-h-cg-amg degree-cg-amg; do
  echo "== $sequence"
  build/penny prms/convergence-$sequence.prm
done
/usr/bin/python3 postprocess/plot_convergence.py output/convergence/convergence \
  output/convergence/uniform-h output/convergence/tip-grading output/convergence/degree output/convergence/adaptive \
  output/convergence/uniform-h-cg-amg output/convergence/degree-cg-amg

# The largest meshes on 2 ranks: MUMPS takes CHOLMOD's place, CG + AMG stays.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for sequence in uniform-h uniform-h-cg-amg degree; do
  echo "== $sequence on 2 MPI ranks"
  sed "s|output/convergence/$sequence\$|output/convergence/$sequence-2-ranks|" prms/convergence-$sequence.prm \
    > output/convergence/$sequence-2-ranks.prm
  mpirun -np 2 build/penny output/convergence/$sequence-2-ranks.prm
done
/usr/bin/python3 postprocess/report_speed_up.py output/convergence uniform-h uniform-h-cg-amg degree
