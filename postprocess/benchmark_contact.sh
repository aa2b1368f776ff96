#!/bin/sh
# The contact solver at full size, one program after the other: its speed
# against the grid on one core (FFTW_ESTIMATE and FFTW_MEASURE plans), the
# grid split over 1 and 2 MPI ranks, then its verification scenes at their
# shipped size (prms/bem-johnson.prm, prms/jkr-sphere.prm,
# prms/bem-bisinusoid.prm): Johnson's sinusoid, the JKR sphere and the
# bi-sinusoid. Each table goes to OUTPUT/<name>.txt with the load average at
# its start and end; timings mean something on an idle machine only.
#
# "ranks" runs benchmark_contact at N = 2048 (or $RANKS_N) under mpirun -np 1
# and -np 2, the grid split in shared memory and by FFTW's MPI plans, with
# each planning, and prints, per planning and split, the speed-up of each
# timed solve on 2 ranks and the largest differences of the results between
# the two runs: A_nc (absolute) and the mean gap (relative) of every solve.
# (As root, Open MPI needs OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1.)
#
# Usage: postprocess/benchmark_contact.sh BUILD_DIR OUTPUT [speed|ranks|verify|all]
# (about: speed 15 minutes, ranks 15 minutes, verify several hours on an idle machine)
set -e
build=$1
output=$2
what=${3:-all}
if [ ! -x "$build/benchmark_contact" ] || { [ ! -x "$build/penny" ] && [ "$what" != speed ] && [ "$what" != ranks ]; } ||
  [ -z "$output" ]; then
  echo "usage: $0 BUILD_DIR OUTPUT [speed|ranks|verify|all] (BUILD_DIR holding benchmark_contact and penny)" >&2
  exit 1
fi
mkdir -p "$output"
if [ "$what" = speed ] || [ "$what" = all ]; then
  "$build/benchmark_contact" > "$output/speed-estimate.txt"
  "$build/benchmark_contact" measure > "$output/speed-measure.txt"
fi
if [ "$what" = ranks ] || [ "$what" = all ]; then
  n=${RANKS_N:-2048}
  for planning in estimate measure; do
    option=$([ $planning = measure ] && echo measure || true)
    mpirun -np 1 "$build/benchmark_contact" $option "$n" > "$output/ranks-$planning-1.txt"
    for split in shared-memory fftw-mpi; do
      mpirun -np 2 "$build/benchmark_contact" $option $([ $split = fftw-mpi ] && echo fftw-mpi || true) "$n" \
        > "$output/ranks-$planning-2-$split.txt"
      # The table's row: | iter time ... | cold time | iter6 time6 | iterA timeA A_nc | ...
      awk -v planning=$planning -v how=$split -v n="$n" '
        FNR == 1 { file++ }
        /^ *[0-9]+ \|/ { split($0, f, "|"); split(f[2], a, " "); split(f[3], b, " "); split(f[4], c, " "); split(f[5], d, " ")
                         single[file] = a[2]; cold[file] = b[4]; six[file] = c[2]; sticky[file] = d[2] }
        /^# result/ { if (file == 1) { area[$4] = $6; gap[$4] = $8 }
                      else { da = $6 - area[$4]; dg = ($8 - gap[$4]) / gap[$4]
                             if (da < 0) da = -da; if (dg < 0) dg = -dg
                             if (da > area_difference) area_difference = da; if (dg > gap_difference) gap_difference = dg } }
        END { printf "%s^2, FFTW %s, grid split %s: wall time on 1 and 2 ranks (s), speed-up\n", n, planning, how
              printf "  six loads 3 ... 0.5 sqrt(V): %8.2f %8.2f  %.2f\n", six[1], six[2], six[1] / six[2]
              printf "  adhesive at 2 sqrt(V):       %8.2f %8.2f  %.2f\n", sticky[1], sticky[2], sticky[1] / sticky[2]
              printf "  from full contact:           %8.2f %8.2f  %.2f\n", single[1], single[2], single[1] / single[2]
              printf "  cold start:                  %8.2f %8.2f  %.2f\n", cold[1], cold[2], cold[1] / cold[2]
              printf "  largest difference 1 vs 2 ranks: A_nc %.1e, mean gap %.1e relative\n", area_difference, gap_difference }
      ' "$output/ranks-$planning-1.txt" "$output/ranks-$planning-2-$split.txt" | tee "$output/ranks-$planning-$split.txt"
    done
  done
fi
if [ "$what" = verify ] || [ "$what" = all ]; then
  prms=$(dirname "$0")/../prms
  for scene in bem-johnson jkr-sphere bem-bisinusoid; do
    "$build/penny" "$prms/$scene.prm" > "$output/$scene.txt"
  done
fi
