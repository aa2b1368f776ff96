#!/usr/bin/python3
"""Draws the non-contact area of sampled random surfaces near full contact:
A_nc/A_0 from the FFT boundary-element solver (mean and standard error over
realisations) against p_bar/sqrt(V), beside the layer's isolated-gap law in
the paper's and the consistent convention, the same law summed over the
lattice's Kac-Rice summits, and Persson's erfc. Reads random-contact.csv.

Usage: /usr/bin/python3 postprocess/plot_random_contact.py OUTPUT_DIR
writes OUTPUT_DIR/random-contact.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "random-contact.csv")
summary = {row["quantity"]: row["value"] for row in read_table(folder, "random-contact-summary.csv")}
load = [row["p_bar/sqrtV"] for row in rows]
figure, axes = plt.subplots(figsize=(6.5, 4.8))
axes.errorbar(load, [row["A_nc/A_0 BEM"] for row in rows], [row["std error"] for row in rows], fmt="ko",
              capsize=3, label="FFT boundary elements")
for column, style in (("linear law paper", "--"), ("linear law consistent", "-"),
                      ("isolated gaps Kac-Rice", "-."), ("Persson erfc", ":")):
    axes.plot(load, [row[column] for row in rows], style, label=column)
axes.set_yscale("log")
axes.set_xlabel(r"mean pressure $\bar p/\sqrt{V}$")
axes.set_ylabel(r"non-contact area $A_{nc}/A_0$")
surface = (f"H, zeta = {summary['H, zeta']}" if "H, zeta" in summary
           else f"spectrum file {summary['spectrum file']}")
axes.set_title(f"{int(summary['realisations'])} realisations on {summary['grid']} grids, {surface}", fontsize=9)
axes.legend(fontsize=8)
figure.tight_layout()
figure.savefig(folder / "random-contact.png", dpi=150)
print(folder / "random-contact.png")
