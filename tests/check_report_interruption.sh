#!/usr/bin/env bash
# Usage: check_report_interruption.sh BUILD_DIR REPORT_SCRIPT SCENES_DIR TRIALS RANKS [SEED [NAME ...]]
# The verification report stopped at random moments, then resumed (issue 68,
# D5 and D6). Each trial starts the report in a session of its own on three
# cheap runs (penny-gap, gap-size-adhesionless, and penny-gap refined once
# with fields, a few seconds; every other trial with --rerun) and sends it,
# after a random delay, SIGINT to
# its whole process group (a terminal's Ctrl-C), SIGTERM (kill PID) or
# SIGKILL. After each: the report ended by that signal (128 + N) or finished
# first, without a Python traceback; no process of the report is left
# (SIGKILL's children end within 15 s); every record is of a run that
# finished and passed, with its complete results. Last, an uninterrupted call
# resumes and reports the same verdicts as a report never interrupted. With
# NAMEs, the runs are SCENES_DIR/NAME.prm instead (issue 68's acceptance:
# prms/ penny-uniform gap-size-adhesionless, 20 trials).
set -u
build=$1 report=$2 scenes=$3 trials=$4 ranks=$5 seed=${6:-$RANDOM}
shift $(($# < 6 ? $# : 6))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fail() { echo "FAIL (seed $seed): $*"; cat "$work/log" 2> /dev/null; exit 1; }

mkdir "$work/prms"
if [ $# -gt 0 ]; then
  runs="$*"
  for name in $runs; do cp "$scenes/$name.prm" "$work/prms/" || fail "no $scenes/$name.prm"; done
else
  cp "$scenes/penny-gap.prm" "$scenes/gap-size-adhesionless.prm" "$work/prms/"
  sed 's/set Directory = out/set Directory = long/' "$scenes/results-long.prm" > "$work/prms/penny-gap-long.prm"
  runs="penny-gap gap-size-adhesionless penny-gap-long"
fi
report() { /usr/bin/python3 "$report" "$build" "$@" -np "$ranks" --prms "$work/prms" $runs; }
verdicts() { grep -E "^\| (${runs// /|}) \|" "$1/report.md" | cut -d'|' -f2-4; }

report "$work/reference" > "$work/log" 2>&1 || fail "the uninterrupted report failed"
reference=$(verdicts "$work/reference")
[ "$(echo "$reference" | grep -c PASS)" = "$(echo $runs | wc -w)" ] || fail "the uninterrupted report does not pass every run"
duration=$(/usr/bin/python3 -c "import json, glob; print(sum(json.load(open(f))['wall time (s)'] + 1 for f in glob.glob('$work/reference/runs/*/record.json')))")

# The live processes whose working folder or command line lies in the report's folder.
left_behind() {
  for process in /proc/[0-9]*; do
    [ "$(sed 's/.*) //' "$process/stat" 2> /dev/null | cut -d' ' -f1)" = Z ] && continue
    { readlink "$process/cwd"; tr '\0' ' ' < "$process/cmdline"; } 2> /dev/null | grep -qF "$work/out" &&
      echo "${process#/proc/}"
  done
}

RANDOM=$seed
signals=(INT TERM KILL)
for trial in $(seq "$trials"); do
  signal=${signals[$((RANDOM % 3))]}
  delay=$(/usr/bin/python3 -c "import random; random.seed($seed * 1000 + $trial); print(round(random.uniform(0, $duration), 2))")
  # Every other trial runs all again (--rerun), the others resume what is recorded.
  rerun=$([ $((trial % 2)) = 1 ] && echo --rerun)
  # A background job of a script ignores SIGINT; a terminal's foreground job does not.
  setsid /usr/bin/python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
    /usr/bin/python3 "$report" "$build" "$work/out" -np "$ranks" --prms "$work/prms" $rerun $runs > "$work/log" 2>&1 &
  pid=$!
  sleep "$delay"
  case $signal in
    INT) kill -INT -- "-$pid" 2> /dev/null ;; # the whole foreground group, as Ctrl-C
    *) kill "-$signal" "$pid" 2> /dev/null ;;
  esac
  wait "$pid"
  status=$?
  declare -A expected=([INT]=130 [TERM]=143 [KILL]=137)
  what="trial $trial: SIG$signal after $delay s${rerun:+ ($rerun)}, exit status $status"
  [ "$status" = 0 ] || [ "$status" = "${expected[$signal]}" ] || fail "$what"
  ! grep -q "Traceback" "$work/log" || fail "$what: a Python traceback"
  if [ "$status" != 0 ] && [ "$signal" != KILL ]; then
    grep -q "^verification_report: stopped by SIG$signal" "$work/log" || fail "$what: no line saying what was kept"
  fi
  for _ in $(seq 150); do
    [ -z "$(left_behind)" ] && break
    sleep 0.1
  done
  [ -z "$(left_behind)" ] || fail "$what: processes left running: $(left_behind | xargs ps -o pid,comm -p)"
  for record in "$work"/out/runs/*/record.json; do
    [ -e "$record" ] || continue
    grep -q '"verdict": "PASS"' "$record" || fail "$what: a record that is not a pass: $(cat "$record")"
    results=$(/usr/bin/python3 -c "import json; print(json.load(open('$record'))['results'])")
    [ -f "$(dirname "$record")/$results/.penny-results" ] || fail "$what: a record without its results"
  done
  echo "ok: $what"
done

report "$work/out" > "$work/log" 2>&1 || fail "the resumed report failed"
[ "$(verdicts "$work/out")" = "$reference" ] || fail "the resumed report's verdicts differ: $(verdicts "$work/out")"
echo "ok: $trials interruptions (seed $seed), then the resumed report's verdicts are the uninterrupted one's"
