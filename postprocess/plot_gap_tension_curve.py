#!/usr/bin/python3
"""Draws the paper's Fig. 2, p_hat = P/p0 against c_hat = c/c_min, from the CSV
that the gap-tension-curve scene writes: FE points over the closed form and the
paper's linear approximation.

Usage: /usr/bin/python3 postprocess/plot_gap_tension_curve.py OUTPUT_DIR
writes OUTPUT_DIR/gap-tension-curve.png"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = pathlib.Path(sys.argv[1])
with open(folder / "gap-tension-curve.csv") as table:
    rows = [{key: float(value) for key, value in row.items()} for row in csv.DictReader(table)]

c_hat = [row["c_hat"] for row in rows]
figure, axes = plt.subplots(figsize=(5.5, 4))
axes.plot(c_hat, [row["p_hat exact"] for row in rows], "k-", label=r"$(\hat c^2 + 4/\sqrt{\hat c})/5$")
axes.plot(c_hat, [row["p_hat linear"] for row in rows], "k--", label="linear approximation")
axes.plot(c_hat, [row["p_hat FE"] for row in rows], "o", mfc="none", color="tab:red", label="FE (J-integral)")
axes.set_xlabel(r"$\hat c = c/c_{min}$")
axes.set_ylabel(r"$\hat p = P/p_0$")
axes.set_title("Gap tension against gap size (paper Fig. 2)")
axes.legend()
figure.tight_layout()
figure.savefig(folder / "gap-tension-curve.png", dpi=150)
print(folder / "gap-tension-curve.png")
