#!/usr/bin/python3
"""The paper's layer on a measured surface: the non-contact area against the
mean pressure of the measured map and of its Gaussian twins (full
boundary-element solutions, error bars the twins' standard error), beside the
isolated-gap law over the map's, the twins' and Kac-Rice's summits and the
paper's linear law in both conventions. Reads measured-analysis.csv.

Usage: /usr/bin/python3 postprocess/plot_measured_analysis.py OUTPUT_DIR
writes OUTPUT_DIR/measured-analysis.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "measured-analysis.csv")
loads = [row["p_bar/sqrtV"] for row in rows]

figure, axes = plt.subplots(figsize=(8, 5.5))
axes.semilogy(loads, [row["A_nc/A_0 BEM map"] for row in rows], "ko-", ms=5, label="BEM, the measured map")
axes.errorbar(loads, [row["BEM twins"] for row in rows], yerr=[row["std error"] for row in rows], fmt="bs-",
              ms=4, capsize=3, label="BEM, its Gaussian twins (same spectrum, random phases)")
for column, style, name in (("isolated gaps map summits", "k--", "isolated gaps over the map's summits"),
                            ("isolated gaps twin summits", "b--", "isolated gaps over the twins' summits"),
                            ("isolated gaps Kac-Rice", "m:", "isolated gaps over Kac-Rice's summits"),
                            ("linear law paper", "r-.", "the paper's linear law (paper's convention)"),
                            ("linear law consistent", "y-.", "the paper's linear law (consistent convention)")):
    values = [(load, row[column]) for load, row in zip(loads, rows) if row[column] > 0]
    axes.semilogy([v[0] for v in values], [v[1] for v in values], style, lw=1.2, label=name)
axes.set_xlabel(r"mean pressure $\bar p/\sqrt{V}$ (dimensionless)")
axes.set_ylabel(r"non-contact area $A_{nc}/A_0$ (dimensionless)")
axes.set_title("A measured surface and its Gaussian twins against the paper's layer (adhesionless)", fontsize=9)
axes.grid(alpha=0.3, which="both")
axes.legend(fontsize=7)
corner_note(figure, folder)
figure.tight_layout(rect=(0, 0.02, 1, 1))
figure.savefig(folder / "measured-analysis.png", dpi=120)
