#!/usr/bin/python3
"""Compares the CSV tables of two result trees, e.g. the output/ folders of two
builds that ran the same scenes: every table of OLD_DIR with its namesake in
NEW_DIR, column by column. A missing folder, a table missing from NEW_DIR or
an OLD_DIR without any table is a failure.

Numbers must agree to RELATIVE (default 1e-12), or to the last digit the less
precise file printed; RELATIVE 0 asks for identical numbers (the same run on
1 and on N MPI ranks). Columns that hold errors or differences of nearly equal
numbers (names with 'error', 'difference' or 'residual') are held to the same bound in
absolute terms. Skipped: run times, memory, the number of MPI ranks, and observed convergence rates
(a rate divides by the log of an error ratio near the discretisation floor,
which magnifies rounding a millionfold). Text must be equal. Prints the
largest deviation per table and exits 1 on any mismatch.

Usage: /usr/bin/python3 postprocess/compare_results.py OLD_DIR NEW_DIR [RELATIVE]"""
import csv
import math
import pathlib
import sys

old_root, new_root = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
bound = float(sys.argv[3]) if len(sys.argv) > 3 else 1e-12


def skipped(column):
    return (
        "(s)" in column
        or "MiB" in column
        or "(MB)" in column
        or column.startswith("wall")
        or column in ("rate", "MPI ranks")
    )


def last_digit(text):
    """Half a unit in the last printed digit of a number."""
    mantissa, _, exponent = text.strip().lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def rows_of(path):
    with open(path) as table:
        return list(csv.DictReader(table))


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare(old_rows, new_rows):
    """The largest deviation and a list of mismatches."""
    problems, worst = [], 0.0
    if len(old_rows) != len(new_rows):
        return worst, [f"{len(old_rows)} rows against {len(new_rows)}"]
    key = "quantity" if old_rows and "quantity" in old_rows[0] else None
    for i, (old, new) in enumerate(zip(old_rows, new_rows)):
        if key and old[key] != new[key]:
            problems.append(f"row {i}: quantity '{old[key]}' against '{new[key]}'")
            continue
        for column, old_text in old.items():
            if column is None or old_text is None:
                problems.append(f"row {i}: more cells than columns")
                continue
            if skipped(column) or (key and skipped(old[key])):
                continue
            if column not in new:
                problems.append(f"column '{column}' missing")
                continue
            a, b = number(old_text), number(new[column])
            if a is None or b is None:
                if old_text.strip() != new[column].strip():
                    problems.append(f"row {i}, '{column}': '{old_text}' against '{new[column]}'")
                continue
            absolute = any(word in column.lower() for word in ("error", "difference", "residual"))
            scale = 1.0 if absolute else max(abs(a), abs(b), 1e-300)
            allowed = max(bound, max(last_digit(old_text), last_digit(new[column])) / scale) if bound > 0 else 0.0
            deviation = 0.0 if a == b else abs(a - b) / scale
            if math.isnan(deviation) or deviation > allowed:
                problems.append(f"row {i}, '{column}': {a!r} against {b!r}")
            worst = max(worst, deviation)
    return worst, problems


for root in (old_root, new_root):
    if not root.is_dir():
        sys.exit(f"compare_results.py: {root} is not a folder")
failed = False
old_tables = sorted(path.relative_to(old_root) for path in old_root.rglob("*.csv"))
if not old_tables:
    sys.exit(f"compare_results.py: {old_root} holds no CSV table")
for relative in old_tables:
    if not (new_root / relative).exists():
        print(f"{relative}: only in {old_root}")
        failed = True
        continue
    worst, problems = compare(rows_of(old_root / relative), rows_of(new_root / relative))
    print(f"{relative}: largest deviation {worst:.1e}" + (f", {len(problems)} mismatches" if problems else ""))
    for problem in problems[:5]:
        print(f"  {problem}")
    failed |= bool(problems)
sys.exit(1 if failed else 0)
