#!/usr/bin/env bash
# The contact solver's grid split over MPI ranks: benchmark_contact
# (postprocess/benchmark_contact.cc) at N = 2048 (or $RANKS_N) under
# mpirun -np 1 and -np 2, the grid split in shared memory and by FFTW's MPI
# plans, with FFTW_ESTIMATE and FFTW_MEASURE plans; then speed-up.md: per
# planning, split and timed solve the wall time on 1 and 2 ranks and the
# speed-up against issue 24's target 1.7, and the largest differences of the
# results between the rank counts (A_nc absolute, the mean gap relative, over
# every solve). About 6 minutes; timings mean something on an idle machine
# only. Exit status 0 when it ran, whether or not the target is met.
# Usage, from anywhere: postprocess/benchmark_contact_ranks.sh [BUILD [OUT]]
# (defaults: build, output/benchmark-contact-ranks, both from the repository root)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(realpath "${1:-$root/build}")"
out="$(realpath -m "${2:-$root/output/benchmark-contact-ranks}")"
n=${RANKS_N:-2048}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
[ -x "$build/benchmark_contact" ] ||
  { echo "$0: $build/benchmark_contact is missing (usage: $0 [BUILD [OUT]], BUILD a build folder)" >&2; exit 1; }
mkdir -p "$out"
runs=()
for planning in estimate measure; do
  option=$([ $planning = measure ] && echo measure || true)
  echo "== benchmark_contact $n^2, FFTW $planning, 1 rank"
  mpirun -np 1 "$build/benchmark_contact" $option "$n" < /dev/null | tee "$out/$planning-1-rank.txt"
  for split in shared-memory fftw-mpi; do
    echo "== benchmark_contact $n^2, FFTW $planning, 2 ranks, grid split by $split"
    mpirun -np 2 "$build/benchmark_contact" $option $([ $split = fftw-mpi ] && echo fftw-mpi || true) "$n" \
      < /dev/null | tee "$out/$planning-2-ranks-$split.txt"
    runs+=("$planning" "$split" "$out/$planning-1-rank.txt" "$out/$planning-2-ranks-$split.txt")
  done
done
# Per planning and split: four rows of speed-up, then one of differences.
speed_rows="" difference_rows=""
for ((k = 0; k < ${#runs[@]}; k += 4)); do
  # A row: | N | iter time ... | cold iter + coarse, time | iter6 time6 | iterA timeA A_nc | ...
  rows=$(awk -v planning="${runs[k]}" -v how="${runs[k + 1]}" '
    FNR == 1 { file++ }
    /^ *[0-9]+ \|/ { split($0, f, "|"); split(f[2], a, " "); split(f[3], b, " "); split(f[4], c, " "); split(f[5], d, " ")
                     time["six loads 3 ... 0.5 sqrt(V)", file] = c[2]; time["adhesive at 2 sqrt(V)", file] = d[2]
                     time["from full contact", file] = a[2]; time["cold start", file] = b[4] }
    /^# result/ { if (file == 1) { area[$4] = $6; gap[$4] = $8 }
                  else { da = $6 - area[$4]; dg = ($8 - gap[$4]) / gap[$4]
                         if (da < 0) da = -da; if (dg < 0) dg = -dg
                         if (da > area_difference) area_difference = da; if (dg > gap_difference) gap_difference = dg } }
    END { split("six loads 3 ... 0.5 sqrt(V)|adhesive at 2 sqrt(V)|from full contact|cold start", solves, "|")
          for (s = 1; s <= 4; ++s) {
            one = time[solves[s], 1]; two = time[solves[s], 2]
            printf "| %s | %s | %s | %.2f | %.2f | %.2f | %s |\n", planning, how, solves[s], one, two, one / two,
                   (one / two >= 1.7 ? "yes" : "no") }
          printf "| %s | %s | %.1e | %.1e |\n", planning, how, area_difference, gap_difference }
  ' "${runs[k + 2]}" "${runs[k + 3]}")
  speed_rows+="$(head -n 4 <<< "$rows")"$'\n'
  difference_rows+="$(tail -n 1 <<< "$rows")"$'\n'
done
{
  echo "| FFTW planning | grid split | solve at $n^2 | 1 rank (s) | 2 ranks (s) | speed-up | at least 1.7 |"
  echo "|---|---|---|---|---|---|---|"
  printf "%s\n" "$speed_rows"
  echo "| FFTW planning | grid split | largest A_nc difference, 1 vs 2 ranks | largest mean gap difference (relative) |"
  echo "|---|---|---|---|"
  printf "%s" "$difference_rows"
} > "$out/speed-up.md.partial"
mv "$out/speed-up.md.partial" "$out/speed-up.md"
cat "$out/speed-up.md"
