#!/usr/bin/env bash
# Runs every convergence sequence (Release build expected in build/), draws
# error against DoFs and against wall time, and solves the largest model of
# three sequences as one penny-gap scene on 1 and on 2 MPI ranks for the
# speed-up of one distributed model. Usage, from the repository root:
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

# The largest models, each one penny-gap solve shared by the ranks: on 2
# ranks MUMPS takes CHOLMOD's place, CG + AMG stays. (On several ranks the
# convergence scene spreads its cycles instead, one model per rank.)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
largest() { # NAME DEGREE TIP_LEVELS GAP_FACE_LEVELS GRADING REFINEMENTS SOLVER
  cat <<PRM
set Scene = penny-gap
subsection Mesh
  set Tip refinement levels = $3
  set Gap face levels       = $4
  set Grading distance      = $5
  set Global refinements    = $6
end
subsection Finite element
  set Polynomial degree = $2
end
subsection Linear solver
  set Type      = $7
  set Tolerance = 1e-10
end
subsection Fields
  set Write fields = false
end
subsection Verification
  set Tolerance = 1
end
subsection Output
  set Directory = output/convergence/largest/$1-RANKS-ranks
end
PRM
}
names=()
while read -r name settings; do
  names+=("$name")
  for ranks in 1 2; do
    echo "== $name on $ranks MPI rank(s)"
    largest "$name" $settings | sed "s/RANKS/$ranks/" > output/convergence/largest-$name-$ranks.prm
    mpirun -np $ranks build/penny output/convergence/largest-$name-$ranks.prm < /dev/null
  done
done <<LIST
uniform-h 2 0 0 2 4 direct
uniform-h-cg-amg 2 0 0 2 4 cg-amg
degree 4 30 3 3 0 direct
LIST
/usr/bin/python3 postprocess/report_speed_up.py output/convergence/largest "${names[@]}"
