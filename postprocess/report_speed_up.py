#!/usr/bin/python3
"""Speed-up of one distributed model on 2 MPI ranks: the penny-gap scenes
FOLDER/NAME-1-ranks and FOLDER/NAME-2-ranks (postprocess/run_convergence_benchmark.sh)
side by side: DoFs, solvers, solve and total wall time (the process start-up
aside), and how far K_I moved.

Usage: /usr/bin/python3 postprocess/report_speed_up.py FOLDER NAME...
prints a table and writes it to FOLDER/speed-up.csv"""
import csv
import pathlib
import sys


def scene(folder):
    with open(folder / "summary.csv") as table:
        summary = {row["quantity"]: row["value"] for row in csv.DictReader(table)}
    with open(folder / "rings.csv") as table:
        rings = [float(row["K_I signed FE (Pa m^1/2)"]) for row in csv.DictReader(table)]
    return summary, rings


folder = pathlib.Path(sys.argv[1])
rows = []
for name in sys.argv[2:]:
    (one, K_one), (two, K_two) = scene(folder / f"{name}-1-ranks"), scene(folder / f"{name}-2-ranks")
    rows.append({
        "model": name, "DoFs": one["DoFs"],
        "solver 1 rank": one["solver"], "solver 2 ranks": two["solver"],
        "solve 1 rank (s)": float(one["wall time solve (s)"]), "solve 2 ranks (s)": float(two["wall time solve (s)"]),
        "wall 1 rank (s)": float(one["wall time total (s)"]), "wall 2 ranks (s)": float(two["wall time total (s)"]),
        "speed-up (wall)": float(one["wall time total (s)"]) / float(two["wall time total (s)"]),
        "K_I relative difference": max(abs(b / a - 1) for a, b in zip(K_one, K_two)),
    })
with open(folder / "speed-up.csv", "w", newline="") as out:
    writer = csv.DictWriter(out, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
for row in rows:
    print(", ".join(f"{key} {value:.3g}" if isinstance(value, float) else f"{key} {value}" for key, value in row.items()))
