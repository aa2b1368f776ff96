#!/usr/bin/python3
"""Draws the paper's Fig. 3 from the zero-load-gap-area scene: the non-contact
area at zero mean pressure against p0/sqrt(V), for the paper's linear gap law
and the exact gap function g; linear and log scales side by side. The title
states the normalisation convention of the run.

Usage: /usr/bin/python3 postprocess/plot_zero_load_gap_area.py OUTPUT_DIR
writes OUTPUT_DIR/zero-load-gap-area.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import convention_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "zero-load-gap-area.csv")
x = [row["p0/sqrtV"] for row in rows]
figure, panels = plt.subplots(1, 2, figsize=(9, 4))
for axes, scale in zip(panels, ("linear", "log")):
    axes.plot(x, [row["A_nc linear closed form"] for row in rows], "k-", label="linear gap law (paper)")
    axes.plot(x, [row["A_nc exact g"] for row in rows], "--", color="tab:red", label="exact g")
    axes.set_yscale(scale)
    axes.set_xlabel(r"$p_0/\sqrt{V}$")
    axes.set_ylabel(r"$A_{nc}(\bar p = 0)/A_0$")
panels[0].legend()
figure.suptitle("Non-contact area at zero load (paper Fig. 3)\n" + convention_note(folder), fontsize=10)
figure.tight_layout()
figure.savefig(folder / "zero-load-gap-area.png", dpi=150)
print(folder / "zero-load-gap-area.png")
