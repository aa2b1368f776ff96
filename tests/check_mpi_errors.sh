#!/usr/bin/env bash
# Usage: check_mpi_errors.sh PENNY SCENE.prm SHIM
# Error paths on 2 MPI ranks: each run must end within 60 s (a hang fails),
# with a non-zero status, penny's one-line message, and the previous results
# in out/ intact. SCENE.prm is a small penny-gap scene writing to out/; SHIM
# is the LD_PRELOAD library of write_failure.cc.
#   - out/ holds a file penny did not write (refused on rank 0, before any solve);
#   - the disk fills while rank 0 writes the VTU gathered from both ranks;
#   - a 3D model too large for the memory, refused on both ranks, naming the
#     limit that binds (the memory shared by the ranks, or ulimit -v);
#   - rank 1 alone fails (its own parameter file, bad) while rank 0 waits
#     for it in a collective operation.
set -u
penny=$1 scene=$2 shim=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$scene" scene.prm

fail() { echo "FAIL: $*"; echo "--- stderr:"; cat stderr; exit 1; }
fingerprint() { (cd out && find . -type f | sort | xargs -r sha256sum); }
# Runs mpirun with the arguments; fails on a hang, exit status 0, a missing message or changed results.
expect_error() {
  local message=$1
  shift
  local before
  before=$(fingerprint)
  timeout -k 5 60 mpirun "$@" > stdout 2> stderr
  local status=$?
  [ $status -ne 124 ] && [ $status -ne 137 ] || fail "hung: no exit within 60 s ($*)"
  [ $status -ne 0 ] || fail "exit status 0 ($*)"
  grep -q "^penny: error.*$message" stderr || fail "no line 'penny: error ... $message' ($*)"
  [ "$(grep -c '^penny: ' stderr)" -eq 1 ] || fail "penny printed more than one line ($*)"
  [ "$(fingerprint)" = "$before" ] || fail "the previous results changed ($*)"
  echo "ok: $(grep '^penny: ' stderr)"
}

mpirun -np 2 "$penny" scene.prm > stdout 2> stderr || fail "a 2-rank run failed"

# A folder penny did not write: refused on every rank.
mkdir -p foreign/solution.vtu
sed 's/set Directory = out/set Directory = foreign/' scene.prm > foreign.prm
expect_error "holds files penny did not write" -np 2 "$penny" foreign.prm

# The disk fills while rank 0 writes.
expect_error "No space left on device" -np 2 -x PENNY_TEST_DISK_BYTES=5000 -x LD_PRELOAD="$shim" "$penny" scene.prm

# A 3D model too large for the memory: refused on both ranks before it is refined.
cp "$(dirname "$scene")/../bad-input/elliptical-too-large.prm" too-large.prm
expect_error "Global refinements = 3, .* per rank; each rank may use .*, shared by 2 ranks, after" \
  -np 2 "$penny" too-large.prm
# The same under an address-space limit, which holds for each rank alone: the line names it.
(ulimit -v 4000000 && expect_error "per rank; each rank may use .* address-space limit (ulimit -v)" \
  -np 2 "$penny" too-large.prm) || exit 1

# Rank 1 alone fails: its parameter file (mpirun's MPMD form) holds a bad
# value, while rank 0 goes on and waits for it in a collective operation.
sed 's/set Directory = out/set Directory = out\nend\nsubsection Material\n  set Poisson'"'"'s ratio nu = 0.5/' \
  scene.prm > rank-1.prm
expect_error "on MPI rank 1 alone: .*Poisson's ratio nu = 0.5" -np 1 "$penny" scene.prm : -np 1 "$penny" rank-1.prm
