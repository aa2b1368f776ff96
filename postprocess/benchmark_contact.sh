#!/bin/sh
# The contact solver at full size, one program after the other on one core:
# its speed against the grid (FFTW_ESTIMATE and FFTW_MEASURE plans), then its
# verification scenes at their shipped size (prms/bem-johnson.prm,
# prms/jkr-sphere.prm, prms/bem-bisinusoid.prm): Johnson's sinusoid, the JKR
# sphere and the bi-sinusoid. Each table goes to OUTPUT/<name>.txt with the load average at
# its start and end; timings mean something on an idle machine only.
#
# Usage: postprocess/benchmark_contact.sh BUILD_DIR OUTPUT [speed|verify|all]
# (about: speed 15 minutes, verify several hours on an idle machine)
set -e
build=$1
output=$2
what=${3:-all}
if [ ! -x "$build/benchmark_contact" ] || [ ! -x "$build/penny" ] || [ -z "$output" ]; then
  echo "usage: $0 BUILD_DIR OUTPUT [speed|verify|all] (BUILD_DIR holding benchmark_contact and penny)" >&2
  exit 1
fi
mkdir -p "$output"
if [ "$what" = speed ] || [ "$what" = all ]; then
  "$build/benchmark_contact" > "$output/speed-estimate.txt"
  "$build/benchmark_contact" measure > "$output/speed-measure.txt"
fi
if [ "$what" = verify ] || [ "$what" = all ]; then
  prms=$(dirname "$0")/../prms
  for scene in bem-johnson jkr-sphere bem-bisinusoid; do
    "$build/penny" "$prms/$scene.prm" > "$output/$scene.txt"
  done
fi
