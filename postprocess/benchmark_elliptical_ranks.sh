#!/usr/bin/env bash
# One 3D model of a million DoFs shared by 1 and by 2 MPI ranks: the
# elliptical gap of prms/elliptical-gap.prm at degree 2 with one global
# refinement (40704 cells, 1,020,663 DoFs, CG with AMG to 1e-10, no fields),
# then the wall time of each phase on both, the speed-up, and how far K_I
# moved (postprocess/report_speed_up.py). About 9 + 5 minutes and 12 GB on
# the 2-core machine; run it on an idle machine.
# Usage, from anywhere: postprocess/benchmark_elliptical_ranks.sh [BUILD [OUT]]
# (defaults: build, output/benchmark-elliptical-ranks, both from the repository root)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${1:-$root/build}")"
out="$(realpath -m "${2:-$root/output/benchmark-elliptical-ranks}")"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
for ranks in 1 2; do
  sed -e 's/^\( *set Polynomial degree *=\).*/\1 2/' \
      -e 's/^\( *set Global refinements *=\).*/\1 1/' \
      -e 's/^\( *set Write fields *=\).*/\1 false/' \
      -e 's/^\( *set Type *=\).*/\1 cg-amg/' \
      -e "s|^\( *set Directory *=\).*|\1 $out/elliptical-gap-$ranks-ranks|" \
      "$root/prms/elliptical-gap.prm" > "$out/elliptical-gap-$ranks-ranks.prm"
  echo "== elliptical-gap on $ranks MPI rank(s)"
  mpirun -np "$ranks" "$build/penny" "$out/elliptical-gap-$ranks-ranks.prm" < /dev/null
done
/usr/bin/python3 "$root/postprocess/report_speed_up.py" "$out" elliptical-gap
