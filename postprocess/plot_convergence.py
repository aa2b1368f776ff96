#!/usr/bin/python3
"""Draws K_I error against DoFs and against wall time, log-log, one curve per
convergence sequence (each its own marker and line style), from the
convergence.csv files the convergence scene writes. The DoFs plot carries
reference slopes DoFs^(-1/2) (a singular field under uniform refinement) and
DoFs^(-3/2).

Usage: /usr/bin/python3 postprocess/plot_convergence.py OUT_PREFIX DIR [DIR ...]
writes OUT_PREFIX-dofs.png and OUT_PREFIX-time.png; each DIR holds a
convergence.csv and names its curve."""
import itertools
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

prefix, folders = sys.argv[1], [pathlib.Path(name) for name in sys.argv[2:]]
tables = {folder.name: read_table(folder, "convergence.csv") for folder in folders}
styles = list(itertools.product(["-", "--", ":", "-."], ["o", "s", "^", "D", "v", "P"]))
for axis, column, label in (("dofs", "DoFs", "degrees of freedom"), ("time", "wall (s)", "wall time (s)")):
    figure, axes = plt.subplots(figsize=(6.5, 4.8))
    for (name, rows), (line, marker) in zip(tables.items(), styles[::7] + styles):
        axes.loglog([row[column] for row in rows], [row["relative error"] for row in rows], line, marker=marker,
                    mfc="none", label=name)
    if axis == "dofs":
        low = min(row["DoFs"] for rows in tables.values() for row in rows)
        high = max(row["DoFs"] for rows in tables.values() for row in rows)
        top = max(row["relative error"] for rows in tables.values() for row in rows)
        for slope, text in ((0.5, r"DoFs$^{-1/2}$"), (1.5, r"DoFs$^{-3/2}$")):
            axes.loglog([low, high], [top, top * (high / low) ** -slope], color="grey", lw=0.8)
            axes.text(high, top * (high / low) ** -slope, text, color="grey", fontsize=8, va="center")
    axes.set_xlabel(label)
    axes.set_ylabel(r"largest relative error of $K_I$ over the rings")
    axes.set_title("Convergence of K_I under uniform pressure (closed form 2 P sqrt(c/pi))", fontsize=10)
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize="small")
    figure.tight_layout()
    figure.savefig(f"{prefix}-{axis}.png", dpi=150)
    print(f"{prefix}-{axis}.png")
