#!/usr/bin/env bash
# Usage: check_interruption.sh PENNY SCENE.prm
# A run stopped by SIGTERM (kill; mpirun passes it on to its ranks) or SIGINT
# (Ctrl-C) while it computes ends by that signal, leaves no staging folder
# beside its output folder, and the previous results in out/ intact: serial,
# and on 2 ranks under mpirun. One that ignores SIGHUP (nohup) runs on
# through it to its results. SCENE.prm is a small penny-gap scene writing
# to out/; the interrupted runs solve a finer copy of it, which takes seconds.
set -u
penny=$1 scene=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'kill -KILL $(jobs -p) 2> /dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
cp "$scene" scene.prm
sed 's/^\( *set Polynomial degree *=\).*/\1 4/; s/^\( *set Tip refinement levels *=.*\)/\1\n  set Global refinements = 2/' \
  scene.prm > slow.prm
grep -q "Global refinements = 2" slow.prm || { echo "FAIL: could not make the slow copy"; exit 1; }

fail() { echo "FAIL: $*"; echo "--- output:"; cat output; exit 1; }
fingerprint() { (cd out && find . -type f | sort | xargs -r sha256sum); }

"$penny" scene.prm > output 2>&1 || fail "the first run failed"
before=$(fingerprint)

# Waits for the slow run's staging folder, then lets it compute a second.
await_staging() {
  for _ in $(seq 300); do
    compgen -G ".out.staging-*" > /dev/null && break
    sleep 0.1
  done
  compgen -G ".out.staging-*" > /dev/null || fail "no staging folder within 30 s ($*)"
  sleep 1
}

# Starts the slow run (the command given), sends the signal once it computes
# and checks the exit status (a pattern) and what is left.
interrupt() {
  local signal=$1 expected_status=$2
  shift 2
  "$@" > output 2>&1 &
  local pid=$!
  await_staging "$@"
  kill -"$signal" $pid
  local status=0
  timeout 60 tail --pid=$pid -f /dev/null || fail "still running 60 s after SIG$signal ($*)"
  wait $pid || status=$?
  # shellcheck disable=SC2254 # the expected status is a pattern
  case $status in
    $expected_status) ;;
    *) fail "exit status $status after SIG$signal, expected $expected_status ($*)" ;;
  esac
  ! compgen -G ".out.staging-*" > /dev/null || fail "a staging folder is left after SIG$signal ($*): $(ls -a)"
  [ "$(fingerprint)" = "$before" ] || fail "the previous results changed after SIG$signal ($*)"
  echo "ok: SIG$signal, exit status $status, no staging folder, previous results intact ($*)"
}

# A script's background job ignores SIGINT, and so does penny then (as it
# keeps ignoring SIGHUP under nohup): env gives it the default back.
interrupt TERM 143 "$penny" slow.prm
interrupt INT 130 env --default-signal=INT "$penny" slow.prm
# nohup: SIGHUP changes nothing, the run ends with its results.
nohup "$penny" slow.prm > output 2>&1 &
pid=$!
await_staging nohup "$penny" slow.prm
kill -HUP $pid
wait $pid || fail "the run under nohup failed after SIGHUP (status $?)"
grep -q "^PASS" output || fail "the run under nohup did not pass after SIGHUP"
[ "$(fingerprint)" != "$before" ] || fail "the run under nohup left the previous results in place"
echo "ok: SIGHUP under nohup, the run went on to its results"
before=$(fingerprint)

# mpirun passes SIGTERM on to the ranks and ends with a failure status of its own.
interrupt TERM "[1-9]*" mpirun -np 2 "$penny" slow.prm
