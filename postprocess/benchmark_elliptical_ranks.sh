#!/usr/bin/env bash
# One 3D model of a million DoFs shared by 1 and by 2 MPI ranks, with each
# iterative solver: the elliptical gap of prms/elliptical-gap.prm (b/a = 0.5)
# at degree 2 with one global refinement on CG + AMG, and at degree 4 on the
# matrix-free CG + p-multigrid (the same DoFs, just over a million),
# tolerance 1e-10, no fields; then the wall time of each phase on both rank
# counts, the speed-up, and how far K_I moved (postprocess/report_speed_up.py).
# About 18 minutes and 13 GB (AMG) plus 1.5 minutes and 1.4 GB (matrix-free)
# on the 2-core machine (1159 s in the report of 2026-11-30); run it idle.
# Usage, from anywhere: postprocess/benchmark_elliptical_ranks.sh [BUILD [OUT]]
# (defaults: build, output/benchmark-elliptical-ranks, both from the repository root)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${1:-$root/build}")"
out="$(realpath -m "${2:-$root/output/benchmark-elliptical-ranks}")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
# name:degree:global refinements:solver
for model in amg:2:1:cg-amg matrix-free:4:0:cg-multigrid; do
  IFS=: read -r name degree refinements solver <<< "$model"
  for ranks in 1 2; do
    run="elliptical-gap-$name-$ranks-ranks"
    sed -e "s/^\( *set Polynomial degree *=\).*/\1 $degree/" \
        -e "s/^\( *set Global refinements *=\).*/\1 $refinements/" \
        -e 's/^\( *set Write fields *=\).*/\1 false/' \
        -e "s/^\( *set Type *=\).*/\1 $solver/" \
        -e "s|^\( *set Directory *=\).*|\1 $out/$run|" \
        "$root/prms/elliptical-gap.prm" > "$out/$run.prm"
    echo "== elliptical-gap, $name, on $ranks MPI rank(s)"
    mpirun -np "$ranks" "$build/penny" "$out/$run.prm" < /dev/null
  done
done
/usr/bin/python3 "$root/postprocess/report_speed_up.py" "$out" elliptical-gap-amg elliptical-gap-matrix-free
