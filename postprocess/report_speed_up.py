#!/usr/bin/python3
"""Speed-up of one distributed model on 2 MPI ranks: the scenes
FOLDER/NAME-1-ranks and FOLDER/NAME-2-ranks (penny-gap from
postprocess/run_convergence_benchmark.sh, elliptical-gap from
postprocess/benchmark_elliptical_ranks.sh) side by side: DoFs, solvers, the
wall time of every phase and in all (the process start-up aside), and how far
K_I moved (every ring, and every front point of an elliptical gap).

Usage: /usr/bin/python3 postprocess/report_speed_up.py FOLDER NAME...
prints a table and writes it to FOLDER/speed-up.csv"""
import csv
import pathlib
import sys


def scene(folder):
    with open(folder / "summary.csv") as table:
        summary = {row["quantity"]: row["value"] for row in csv.DictReader(table)}
    sifs = folder / "rings.csv"
    if not sifs.exists():
        sifs = folder / "front.csv"
    with open(sifs) as table:
        K = [float(value) for row in csv.DictReader(table)
             for key, value in row.items() if key.startswith("K_I signed FE")]
    return summary, K


folder = pathlib.Path(sys.argv[1])
rows = []
for name in sys.argv[2:]:
    (one, K_one), (two, K_two) = scene(folder / f"{name}-1-ranks"), scene(folder / f"{name}-2-ranks")
    if len(K_one) != len(K_two) or not K_one:
        sys.exit(f"report_speed_up: {name}: the two runs have different front points or rings")
    row = {"model": name, "DoFs": one["DoFs"], "solver 1 rank": one["solver"], "solver 2 ranks": two["solver"]}
    for key in one:
        if key.startswith("wall time") and key in two:
            phase = key.removeprefix("wall time ").removesuffix(" (s)")
            row[f"{phase} 1 rank (s)"] = float(one[key])
            row[f"{phase} 2 ranks (s)"] = float(two[key])
            row[f"{phase} speed-up"] = float(one[key]) / float(two[key])
    row["K_I relative difference"] = max(abs(b / a - 1) for a, b in zip(K_one, K_two))
    rows.append(row)
with open(folder / "speed-up.csv", "w", newline="") as out:
    writer = csv.DictWriter(out, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
for row in rows:
    print(", ".join(f"{key} {value:.3g}" if isinstance(value, float) else f"{key} {value}" for key, value in row.items()))
