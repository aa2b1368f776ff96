#!/usr/bin/python3
"""Draws K_I error against DoFs and against wall time, log-log, one curve per
convergence sequence, from the convergence.csv files the convergence scene
writes.

Usage: /usr/bin/python3 postprocess/plot_convergence.py OUT_PREFIX DIR [DIR ...]
writes OUT_PREFIX-dofs.png and OUT_PREFIX-time.png; each DIR holds a
convergence.csv and names its curve."""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(folder):
    with open(folder / "convergence.csv") as table:
        rows = list(csv.DictReader(table))
    return ([float(row["DoFs"]) for row in rows],
            [float(row["wall (s)"]) for row in rows],
            [float(row["relative error"]) for row in rows])


prefix, folders = sys.argv[1], [pathlib.Path(name) for name in sys.argv[2:]]
for axis, column, label in (("dofs", 0, "degrees of freedom"), ("time", 1, "wall time (s)")):
    figure, axes = plt.subplots(figsize=(6, 4.5))
    for folder in folders:
        data = read(folder)
        axes.loglog(data[column], data[2], "o-", label=folder.name)
    axes.set_xlabel(label)
    axes.set_ylabel(r"largest relative error of $K_I$ over the rings")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(f"{prefix}-{axis}.png", dpi=150)
    print(f"{prefix}-{axis}.png")
