#!/usr/bin/env bash
# Convergence of the 3D elliptical gap under uniform pressure (Green-Sneddon)
# and under a summit's quadratic tension p (1 - (x^2/a^2 + y^2/b^2)/2)
# (Galin), in p and in h, for b/a = 1, 0.5, 0.25 and 0.1: prms/elliptical-gap.prm
# (default mesh, 17 front points, rings 0.1, 0.2, 0.4 b^2/a) at degrees 1, 2, 3 and at degrees
# 1, 2 with one global refinement with CG + AMG, and at degrees 4 and 5 with
# the matrix-free CG + p-multigrid, all to 1e-10, on 2 MPI ranks without
# fields; then the table of the largest K_I error against DoFs, wall time and
# peak memory (postprocess/report_elliptical_convergence.py). b/a = 0.1 on
# the direct solver, Q1 and Q2 only (at Q2 and above the mesh's mapped cells
# are inverted there: the matrix-free solver refuses it, MUMPS solves the
# indefinite system). About an hour and a half per traction (three hours in
# all) on the 2-core machine; run it on an idle machine.
# Usage, from anywhere: postprocess/benchmark_elliptical_convergence.sh [BUILD [OUT]]
# (defaults: build, output/benchmark-elliptical-convergence, both from the repository root)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${1:-$root/build}")"
out="$(realpath -m "${2:-$root/output/benchmark-elliptical-convergence}")"
[ -x "$build/penny" ] || { echo "benchmark_elliptical_convergence.sh: no penny in '$build'" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
source "$root/postprocess/scene_copy.sh"
for traction in uniform:0 summit:-0.5; do
  IFS=: read -r load term <<< "$traction"
  for aspect in 1 0.5 0.25 0.1; do
    # degree:global refinements:solver
    discretisations="1:0:cg-amg 2:0:cg-amg 3:0:cg-amg 1:1:cg-amg 2:1:cg-amg 4:0:cg-multigrid 5:0:cg-multigrid"
    if [ "$aspect" = 0.1 ]; then discretisations="1:0:direct 2:0:direct 1:1:direct"; fi
    for discretisation in $discretisations; do
      IFS=: read -r degree refinements solver <<< "$discretisation"
      name="$load-b$aspect-q$degree-r$refinements"
      # "Tolerance = 1e-4" is the verification's, not the solver's.
      scene_copy "$root/prms/elliptical-gap.prm" "$out/$name.prm" \
        "Aspect ratio b/a" "$aspect" "Traction x^2 term c_x" "$term" "Traction y^2 term c_y" "$term" \
        "Global refinements" "$refinements" "Polynomial degree" "$degree" "Type" "$solver" \
        "Write fields" false "Tolerance = 1e-4" 1 "Directory" "$out/$name"
      echo "== $name ($(date +%T))"
      mpirun -np 2 "$build/penny" "$out/$name.prm" < /dev/null > "$out/$name.log" 2>&1 || {
        echo "benchmark_elliptical_convergence.sh: $name failed:" >&2
        tail -3 "$out/$name.log" >&2
        exit 1
      }
    done
  done
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores)"
/usr/bin/python3 "$root/postprocess/report_elliptical_convergence.py" "$out"
