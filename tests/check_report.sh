#!/usr/bin/env bash
# Usage: check_report.sh BUILD_DIR REPORT_SCRIPT SCENES_DIR
# The verification report at test size: two scenes pass and are reported,
# a second call resumes from their records and rewrites a document's
# generated blocks (--documents), a relative report folder keeps its figures, a check broken on purpose (a
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
# The documents' generated blocks: claims, a run's row, a file of its results; a block of a run not in
# the report is kept; a block not closed, or not saying what it holds, is refused.
printf 'top\n<!-- report: claims -->\nold table\n<!-- report: end -->\nmiddle\n<!-- report: runs penny-gap -->\nold row\n<!-- report: end -->\n<!-- report: file gap-size-adhesionless gap-size.csv -->\nold file\n<!-- report: end -->\n<!-- report: runs jkr-sphere -->\nkept\n<!-- report: end -->\n<!-- report: file penny-gap picture-opening.png -->\n<!-- report: end -->\nbottom\n' > "$work/README.md"
run "$work/good" --prms "$scenes" gap-size-adhesionless penny-gap --documents "$work/README.md" ||
  fail "exit status $? when resuming"
[ "$(grep -c '(recorded ' "$work/log")" = 2 ] || fail "a second call ran recorded scenes again"
grep -q "^| adhesionless gap c/a = sqrt(3/2) | doc/theory.md section 1 | gap-size-adhesionless | PASS |" \
  "$work/README.md" || fail "--documents did not write the claims table"
grep -q "^| penny-gap | PASS | " "$work/README.md" || fail "--documents did not write the run's row"
grep -A3 "^<!-- report: file gap-size-adhesionless gap-size.csv -->" "$work/README.md" | grep -q '^`gap-size.csv`.*' ||
  fail "--documents did not write the file block"
sed -n '/file gap-size-adhesionless/,/report: end/p' "$work/README.md" | grep -q "^|---|" ||
  fail "--documents did not write gap-size.csv as a table"
grep -q '^!\[picture-opening.png of run penny-gap\](figures/penny-gap-picture-opening.png)$' "$work/README.md" ||
  fail "--documents did not show the figure"
cmp -s "$work/figures/penny-gap-picture-opening.png" "$work/good/runs/penny-gap/penny-gap/picture-opening.png" ||
  fail "--documents did not copy the figure beside the document"
grep -q "old" "$work/README.md" && fail "--documents kept an old block"
grep -q "^kept$" "$work/README.md" || fail "--documents rewrote the block of a run not in the report"
grep -q "kept the block 'runs jkr-sphere' (not in this report: jkr-sphere)" "$work/log" ||
  fail "--documents does not say which block it kept"
grep -q "did not run: .*jkr-sphere" "$work/README.md" || fail "--documents does not list the files not run"
[ "$(head -1 "$work/README.md")$(tail -1 "$work/README.md")" = topbottom ] || fail "--documents changed the rest"
grep -q "^middle$" "$work/README.md" || fail "--documents changed the text between blocks"
for broken in $'<!-- report: claims -->\nnever closed' $'<!-- report: everything -->\n<!-- report: end -->' \
  $'<!-- report: file penny-gap ../../secret -->\n<!-- report: end -->'; do
  printf '%s\n' "$broken" > "$work/plain.md"
  run "$work/good" --prms "$scenes" penny-gap --documents "$work/plain.md"
  [ $? = 2 ] || fail "--documents on '$broken' did not exit 2"
done

# A report folder given relative to the working folder: the runs and their figures find it from their own folders.
(cd "$work" && /usr/bin/python3 "$report" "$build" relative --prms "$scenes" bem-westergaard > "$work/log" 2>&1) ||
  fail "exit status $? with a relative report folder (a figure lost?)"
[ -n "$(find "$work/relative/runs/bem-westergaard" -name "*.png")" ] || fail "no figure with a relative report folder"

# A Latin-1 byte in a comment (penny accepts it), found in --prms and named; an output folder with a blank
# in its name: its figures drawn and its results named (hostile campaign D4, D8).
mkdir "$work/odd"
printf '# caf\xe9: a Latin-1 comment\n' | cat - "$scenes/gap-size-adhesionless.prm" > "$work/odd/gap-size-adhesionless.prm"
sed 's|^\( *set Directory *=\).*|\1 output/penny gap|' "$scenes/penny-gap.prm" > "$work/odd/penny-gap-blank.prm"
run "$work/odd-report" --prms "$work/odd" || fail "exit status $? on a Latin-1 comment (found in --prms)"
run "$work/odd-report" --prms "$work/odd" --rerun gap-size-adhesionless penny-gap-blank ||
  fail "exit status $? on a Latin-1 comment and a blank in the output folder (named)"
grep -q '"results": "output/penny gap"' "$work/odd-report/runs/penny-gap-blank/record.json" ||
  fail "the results folder with a blank is not recorded"
[ -n "$(find "$work/odd-report/runs/penny-gap-blank/output/penny gap" -name "*.png")" ] ||
  fail "no figure drawn for an output folder with a blank"
grep -q "^2 of 2 runs passed" "$work/odd-report/report.md" || fail "the odd files are not reported as passed"

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
