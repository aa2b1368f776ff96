#!/usr/bin/env bash
# Usage: check_results.sh PENNY SCENES SHIM CASE
# Attacks a run's output folder; SCENES holds results.prm (small) and
# results-long.prm (a few seconds), SHIM is the LD_PRELOAD library of
# write_failure.cc. Each CASE checks that a run's results appear all together
# or not at all:
#   disk-full-injected  write() fails with ENOSPC after N bytes, for several N
#   disk-full-tmpfs     a real full disk: a small tmpfs (skipped, status 77,
#                       where this machine allows no mount)
#   kill-before-swap    SIGKILL with the results staged, before the swap
#   kill-after-swap     SIGKILL after the swap, before the old results go
#   kill-mid-run        SIGKILL at several moments of a long run
#   removal-cut-short   what a removal of a staging folder leaves when a kill
#                       cuts it short: files, and no marker (hostile campaign D3)
#   concurrent-runs     a second run on a folder a run holds, and runs started together
#   planted-links       symbolic links at the lock and staging names
#   input-in-output     an output folder that holds the parameter file or the working folder
set -u
penny=$1 scenes=$2 shim=$3 case=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$scenes/results.prm" small.prm
cp "$scenes/results-long.prm" long.prm

fail() { echo "FAIL ($case): $*"; [ -f stderr ] && { echo "--- stderr:"; cat stderr; }; exit 1; }

# Every file of out/, hidden ones too, with its checksum.
fingerprint() { (cd out && find . -type f | sort | xargs -r sha256sum); }
staging_folders() { ls -A | grep -c '^\.out\.staging-'; }
complete_set() {
  for file in .penny-results parameters.prm rings.csv summary.csv solution.vtu solution.pvd; do
    [ -s "out/$file" ] || return 1
  done
  tail -c 100 out/solution.vtu | grep -q '</VTKFile>'
}

# A first, complete result.
"$penny" small.prm > stdout 2> stderr || fail "the first run failed"
complete_set || fail "the first run left an incomplete set"
before=$(fingerprint)

same_as_before() { [ "$(fingerprint)" = "$before" ]; }
one_line_containing() {
  [ "$(wc -l < stderr)" -eq 1 ] || fail "stderr is not one line"
  grep -qF -- "$1" stderr || fail "stderr lacks: $1"
}

case $case in
  disk-full-injected)
    # From nothing written to the middle of the VTU and past it to parameters.prm.
    vtu=$(stat -c %s out/solution.vtu)
    for bytes in 0 40 $((vtu / 2)) $((vtu + 1000)); do
      PENNY_TEST_DISK_BYTES=$bytes LD_PRELOAD=$shim "$penny" small.prm > stdout 2> stderr
      [ $? -ne 0 ] || fail "exit status 0 with the disk full after $bytes bytes"
      one_line_containing "No space left on device"
      same_as_before || fail "the previous results changed (disk full after $bytes bytes)"
      [ "$(staging_folders)" -eq 0 ] || fail "a staging folder was left behind"
    done
    # With room enough the same run succeeds: the injection itself breaks nothing.
    PENNY_TEST_DISK_BYTES=100000000 LD_PRELOAD=$shim "$penny" small.prm > stdout 2> stderr || fail "a run with room failed"
    complete_set || fail "a run with room left an incomplete set"
    ;;
  disk-full-tmpfs)
    # A tmpfs that holds the previous results but not the new VTU, in a
    # private mount namespace. Skipped where this machine allows no mount.
    unshare -m true 2> /dev/null || { echo "skipped: no mount namespace"; exit 77; }
    size=$(($(du -sk out | cut -f1) + 64))
    cat > full-disk.sh <<EOF
set -u
mkdir -p disk
mount -t tmpfs -o size=${size}k tmpfs disk || exit 77
cp -a out disk/out
cd disk
before=\$(cd out && find . -type f | sort | xargs sha256sum)
sed 's/Tip refinement levels = 12/Tip refinement levels = 20/' ../small.prm > ../bigger.prm
"$penny" ../bigger.prm > ../stdout 2> ../stderr
status=\$?
after=\$(cd out && find . -type f | sort | xargs sha256sum)
[ \$status -ne 0 ] || { echo "exit status 0 on a full disk"; exit 1; }
[ "\$before" = "\$after" ] || { echo "the previous results changed"; exit 1; }
[ -z "\$(ls -A | grep staging)" ] || { echo "a staging folder was left behind"; exit 1; }
exit 0
EOF
    unshare -m bash full-disk.sh
    status=$?
    [ $status -eq 77 ] && { echo "skipped: tmpfs cannot be mounted here"; exit 77; }
    [ $status -eq 0 ] || fail "$(cat stdout | tail -1)"
    one_line_containing "No space left on device"
    ;;
  kill-before-swap | kill-after-swap)
    moment=${case#kill-}
    moment=${moment%-swap}
    PENNY_TEST_KILL_AT_RENAME=$moment LD_PRELOAD=$shim "$penny" small.prm > stdout 2> stderr
    [ $? -eq 137 ] || fail "penny was not killed"
    if [ "$moment" = before ]; then
      same_as_before || fail "the previous results changed"
    else
      complete_set || fail "the swapped-in results are incomplete"
      ! same_as_before || fail "the new results are not in place"
    fi
    [ "$(staging_folders)" -eq 1 ] || fail "expected the killed run's staging folder"
    # The next run removes it, and leaves a complete set.
    "$penny" small.prm > stdout 2> stderr || fail "the run after the kill failed"
    [ "$(staging_folders)" -eq 0 ] || fail "the next run left the stale staging folder"
    complete_set || fail "the run after the kill left an incomplete set"
    ;;
  removal-cut-short)
    # An interrupted run's removal of its staging folder (or of the previous
    # results swapped into it) can lose the marker before the files.
    cp -a out .out.staging-Ab12Cd
    rm .out.staging-Ab12Cd/.penny-results
    "$penny" small.prm > stdout 2> stderr || fail "the run after the cut-short removal failed"
    [ "$(staging_folders)" -eq 0 ] || fail "the next run left the stale staging folder: $(ls -A)"
    complete_set || fail "the run after the cut-short removal left an incomplete set"
    ;;
  kill-mid-run)
    "$penny" long.prm > stdout 2> stderr || fail "the long run failed"
    before=$(fingerprint)
    for delay in 0.2 0.6 1.0 1.5 2.0 3.0; do
      "$penny" long.prm > stdout 2> stderr &
      pid=$!
      sleep $delay
      kill -KILL $pid 2> /dev/null
      wait $pid 2> /dev/null
      same_as_before || complete_set || fail "killed after $delay s: neither the previous nor a complete set"
      before=$(fingerprint)
    done
    "$penny" small.prm > stdout 2> stderr || fail "the run after the kills failed"
    [ "$(staging_folders)" -eq 0 ] || fail "stale staging folders were left"
    ;;
  concurrent-runs)
    "$penny" long.prm > first.log 2> first.err &
    first=$!
    for _ in $(seq 600); do
      [ "$(staging_folders)" -gt 0 ] && break
      sleep 0.05
    done
    [ "$(staging_folders)" -gt 0 ] || fail "the first run never staged its results"
    timeout 30 "$penny" small.prm > stdout 2> stderr
    status=$?
    [ $status -eq 1 ] || fail "the second run on a held folder ended with status $status"
    one_line_containing "is in use by another penny run"
    wait $first || fail "the first run failed beside the second"
    complete_set || fail "the first run left an incomplete set"
    /usr/bin/python3 -c "import sys, xml.etree.ElementTree as E; E.parse('out/solution.vtu')" || fail "invalid VTU"
    # Runs started together: each succeeds or refuses in one line; the folder ends complete.
    for trial in 1 2 3; do
      "$penny" small.prm > a.log 2> a.err &
      a=$!
      "$penny" small.prm > b.log 2> b.err &
      b=$!
      wait $a; status_a=$?
      wait $b; status_b=$?
      for run in a b; do
        status=$([ $run = a ] && echo $status_a || echo $status_b)
        if [ "$status" -ne 0 ]; then
          [ "$(wc -l < $run.err)" -eq 1 ] && grep -q "is in use by another penny run" $run.err ||
            fail "trial $trial: run $run failed otherwise: $(cat $run.err)"
        fi
      done
      [ $status_a -eq 0 ] || [ $status_b -eq 0 ] || fail "trial $trial: neither run succeeded"
      complete_set || fail "trial $trial: incomplete set"
      /usr/bin/python3 -c "import xml.etree.ElementTree as E; E.parse('out/solution.vtu')" || fail "trial $trial: invalid VTU"
      [ "$(staging_folders)" -eq 0 ] || fail "trial $trial: a staging folder was left"
    done
    ;;
  planted-links)
    echo "victim" > victim
    rm -f .out.lock && ln -s victim .out.lock
    "$penny" small.prm > stdout 2> stderr
    [ $? -ne 0 ] || fail "a symbolic link at the lock file was followed"
    one_line_containing "lock file"
    [ "$(cat victim)" = victim ] || fail "the link's target was changed"
    same_as_before || fail "the previous results changed"
    rm .out.lock
    mkdir victim-folder && echo kept > victim-folder/file
    ln -s victim-folder .out.staging-AAAAAA
    "$penny" small.prm > stdout 2> stderr || fail "a run beside a planted staging link failed"
    [ "$(cat victim-folder/file)" = kept ] || fail "the staging cleanup followed a link"
    complete_set || fail "incomplete set"
    ;;
  input-in-output)
    cp small.prm out/parameters.prm
    cp out/parameters.prm input-copy.prm
    "$penny" out/parameters.prm > stdout 2> stderr
    [ $? -ne 0 ] || fail "a run replaced the folder holding its parameter file"
    one_line_containing "holds the input file"
    cmp -s out/parameters.prm input-copy.prm || fail "the parameter file was overwritten"
    sed 's/set Directory = out/set Directory = ./' small.prm > here.prm
    "$penny" here.prm > stdout 2> stderr
    [ $? -ne 0 ] || fail "a run replaced the working folder"
    one_line_containing "holds the working folder"
    [ -f here.prm ] || fail "the parameter file was removed"
    ;;
  *)
    fail "unknown case"
    ;;
esac
echo "ok ($case)"
