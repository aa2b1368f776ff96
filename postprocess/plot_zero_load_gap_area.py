#!/usr/bin/python3
"""Draws the paper's Fig. 3: the non-contact area at zero mean pressure against
p0/sqrt(V), linear law (the paper's curve), exact gap function g, from the
zero-load-gap-area scene; linear and log scales side by side.

Usage: /usr/bin/python3 postprocess/plot_zero_load_gap_area.py OUTPUT_DIR
writes OUTPUT_DIR/zero-load-gap-area.png"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = pathlib.Path(sys.argv[1])
with open(folder / "zero-load-gap-area.csv") as table:
    rows = [{key: float(value) for key, value in row.items()} for row in csv.DictReader(table)]

x = [row["p0/sqrtV"] for row in rows]
figure, panels = plt.subplots(1, 2, figsize=(9, 3.8))
for axes, scale in zip(panels, ("linear", "log")):
    axes.plot(x, [row["A_nc linear closed form"] for row in rows], "k-", label="linear law (paper)")
    axes.plot(x, [row["A_nc exact g"] for row in rows], "--", color="tab:red", label="exact g")
    axes.set_yscale(scale)
    axes.set_xlabel(r"$p_0/\sqrt{V}$")
    axes.set_ylabel(r"$A_{nc}(\bar p = 0)/A_0$")
panels[0].legend()
figure.suptitle("Non-contact area at zero load (paper Fig. 3)")
figure.tight_layout()
figure.savefig(folder / "zero-load-gap-area.png", dpi=150)
print(folder / "zero-load-gap-area.png")
