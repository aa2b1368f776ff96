#!/usr/bin/env bash
# Usage: check_report.sh BUILD_DIR REPORT_SCRIPT SCENES_DIR
# The verification report at test size: two scenes pass and are reported,
# a second call resumes from their records and writes the claims table into
# a README's block (--readme), a check broken on purpose (a
# tolerance no discretisation meets) is reported as FAIL with exit status 1,
# and a bad argument exits 2.
set -u
build=$1 report=$2 scenes=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; cat "$work/log" 2>/dev/null; exit 1; }
run() { /usr/bin/python3 "$report" "$build" "$@" > "$work/log" 2>&1; }

run "$work/good" --prms "$scenes" gap-size-adhesionless penny-gap || fail "exit status $? for passing scenes"
grep -q "^2 of 2 runs passed" "$work/good/report.md" || fail "report.md lacks '2 of 2 runs passed'"
grep -q "| adhesionless gap c/a = sqrt(3/2) | doc/theory.md section 1 | gap-size-adhesionless | PASS |" \
  "$work/good/report.md" || fail "the paper's claim c/a = sqrt(3/2) is not reported as PASS"
grep -q "<td class=\"PASS\">PASS</td>" "$work/good/report.html" || fail "report.html lacks a PASS cell"
grep -q "^- commit: $(git -C "$(dirname "$report")" rev-parse --short=10 HEAD)" "$work/good/report.md" ||
  fail "report.md does not name the commit of the build's sources"
printf 'top\n<!-- verification report: begin -->\nold table\n<!-- verification report: end -->\nbottom\n' > "$work/README.md"
run "$work/good" --prms "$scenes" --readme "$work/README.md" gap-size-adhesionless penny-gap ||
  fail "exit status $? when resuming"
[ "$(grep -c '(recorded ' "$work/log")" = 2 ] || fail "a second call ran recorded scenes again"
grep -q "^| adhesionless gap c/a = sqrt(3/2) | doc/theory.md section 1 | gap-size-adhesionless | PASS |" \
  "$work/README.md" || fail "--readme did not write the claims table"
grep -q "old table" "$work/README.md" && fail "--readme kept the old block"
grep -q "did not run: .*jkr-sphere" "$work/README.md" || fail "--readme does not list the files not run"
[ "$(head -1 "$work/README.md")$(tail -1 "$work/README.md")" = topbottom ] || fail "--readme changed the rest"
echo "no block" > "$work/plain.md"
run "$work/good" --prms "$scenes" --readme "$work/plain.md" penny-gap
[ $? = 2 ] || fail "--readme on a file without the block did not exit 2"

mkdir "$work/broken"
sed 's/^\( *set Tolerance *=\).*/\1 1e-12/' "$scenes/gap-size-adhesionless.prm" > "$work/broken/gap-size-adhesionless.prm"
run "$work/bad" --prms "$work/broken"
[ $? = 1 ] || fail "a failing check did not exit 1"
grep -q "| gap-size-adhesionless | PASS\|^2 of" "$work/bad/report.md" && fail "a failing check reported as passed"
grep -q "| gap-size-adhesionless | FAIL |" "$work/bad/report.md" || fail "report.md lacks the FAIL row"

run "$work/args" -np 0 --prms "$scenes" gap-size-adhesionless
[ $? = 2 ] || fail "-np 0 did not exit 2"
grep -q "np = 0 is outside the allowed range" "$work/log" || fail "-np 0 message"
echo "ok: the report passes, resumes, fails and refuses as it should"
