#!/usr/bin/env bash
# Runs every convergence sequence (Release build expected in build/) and draws
# error against DoFs and against wall time. Usage, from the repository root:
#   postprocess/run_convergence_benchmark.sh
set -euo pipefail
cd "$(dirname "$0")/.."
for sequence in uniform-h tip-grading degree domain-size uniform-h-cg-amg degree-cg-amg; do
  echo "== $sequence"
  build/penny prms/convergence-$sequence.prm
done
/usr/bin/python3 postprocess/plot_convergence.py output/convergence/convergence \
  output/convergence/uniform-h output/convergence/tip-grading output/convergence/degree \
  output/convergence/uniform-h-cg-amg output/convergence/degree-cg-amg
