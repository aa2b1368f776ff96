#!/usr/bin/env bash
# Usage: check_unit_suites.sh UNIT_TESTS TESTS_DIR
# ctest runs the unit tests suite by suite (--run_test=NAME), so a test case
# outside the suite of its file would never run: the program's top level must
# list exactly one suite per tests/test_*.cc, named as the file.
set -u
listed=$("$1" --list_content 2>&1 | grep -v '^ ' | tr -d '*' | sort)
expected=$(cd "$2" && ls test_*.cc | sed 's/\.cc$//' | sort)
if [ "$listed" = "$expected" ]; then
  echo "ok: $(echo "$expected" | wc -l) suites, one per file"
  exit 0
fi
echo "FAIL: the unit tests' top level is not one suite per file (< files, > program):"
diff <(echo "$expected") <(echo "$listed")
exit 1
