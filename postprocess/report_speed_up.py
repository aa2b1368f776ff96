#!/usr/bin/python3
"""Speed-up on 2 MPI ranks: the last (largest) cycle of each convergence
sequence on 1 rank (FOLDER/NAME) beside 2 ranks (FOLDER/NAME-2-ranks).

Usage: /usr/bin/python3 postprocess/report_speed_up.py FOLDER NAME...
prints a table and writes it to FOLDER/speed-up.csv"""
import csv
import pathlib
import sys


def largest_cycle(folder):
    with open(folder / "convergence.csv") as table:
        return list(csv.DictReader(table))[-1]


folder = pathlib.Path(sys.argv[1])
rows = []
for name in sys.argv[2:]:
    one, two = largest_cycle(folder / name), largest_cycle(folder / f"{name}-2-ranks")
    rows.append({
        "sequence": name, "DoFs": one["DoFs"],
        "solver 1 rank": one["solver"], "solver 2 ranks": two["solver"],
        "solve 1 rank (s)": float(one["solve (s)"]), "solve 2 ranks (s)": float(two["solve (s)"]),
        "wall 1 rank (s)": float(one["wall (s)"]), "wall 2 ranks (s)": float(two["wall (s)"]),
        "speed-up (wall)": float(one["wall (s)"]) / float(two["wall (s)"]),
        "K_I relative difference": max(abs(float(two[key]) / float(one[key]) - 1)
                                       for key in one if key.startswith("K_I ring")),
    })
with open(folder / "speed-up.csv", "w", newline="") as out:
    writer = csv.DictWriter(out, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
for row in rows:
    print(", ".join(f"{key} {value:.3g}" if isinstance(value, float) else f"{key} {value}" for key, value in row.items()))
