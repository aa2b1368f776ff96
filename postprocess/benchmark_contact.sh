#!/bin/sh
# The contact solver at full size, one program after the other on one core:
# its speed against the grid (FFTW_ESTIMATE and FFTW_MEASURE plans), then its
# verification against Johnson's sinusoid, the JKR sphere and the
# bi-sinusoid. Each table goes to OUTPUT/<name>.txt with the load average at
# its start and end; timings mean something on an idle machine only.
#
# Usage: postprocess/benchmark_contact.sh BUILD_DIR OUTPUT [speed|verify|all]
# (about: speed 15 minutes, verify several hours on an idle machine)
set -e
build=$1
output=$2
what=${3:-all}
if [ ! -x "$build/benchmark_contact" ] || [ ! -x "$build/verify_contact" ] || [ -z "$output" ]; then
  echo "usage: $0 BUILD_DIR OUTPUT [speed|verify|all] (BUILD_DIR holding benchmark_contact and verify_contact)" >&2
  exit 1
fi
mkdir -p "$output"
if [ "$what" = speed ] || [ "$what" = all ]; then
  "$build/benchmark_contact" > "$output/speed-estimate.txt"
  "$build/benchmark_contact" measure > "$output/speed-measure.txt"
fi
if [ "$what" = verify ] || [ "$what" = all ]; then
  for problem in sinusoid bisinusoid sphere; do
    "$build/verify_contact" $problem > "$output/verify-$problem.txt"
  done
fi
