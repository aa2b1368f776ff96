#!/usr/bin/python3
"""Draws the paper's "elliptical form" question against the summits' aspect
ratio Ay/Ax: the gap-area ratio of the adhesionless gap (3/2 for the circle,
the factor the statistical layer multiplies by) and psi of the adhesive
minimum (1.2021 for the circle), FE with the estimate |FE - coarse FE| as
error bars beside Galin's closed form. Reads adhesionless.csv and adhesive.csv.

Usage: /usr/bin/python3 postprocess/plot_elliptical_summits.py OUTPUT_DIR
writes OUTPUT_DIR/elliptical-summits.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
panels = (("adhesionless.csv", "gap area/tension area", 1.5, "without adhesion: gap area / tension area"),
          ("adhesive.csv", "psi", 1.2020809449045589, r"with adhesion: $\psi = p_0/(K_{Ic}^4/R_p)^{1/5}$"))
figure, axes = plt.subplots(1, 2, figsize=(10, 4.2))
for axis, (table, name, circle, title) in zip(axes, panels):
    rows = read_table(folder, table)
    ratio = [row["Ay/Ax"] for row in rows]
    axis.errorbar(ratio, [row[name + " FE"] for row in rows], [row[name + " FE error estimate"] for row in rows],
                  fmt="ko", capsize=3, label="3D FE (bars: |FE - coarse FE|)")
    axis.plot(ratio, [row[name + " exact"] for row in rows], "b-", label="Galin's closed form")
    axis.axhline(circle, color="gray", linestyle="--", label=f"axisymmetric (paper): {circle:.4f}")
    axis.set_xlabel("summit aspect ratio Ay/Ax")
    axis.set_title(title, fontsize=10)
    axis.legend(fontsize=8)
figure.tight_layout()
figure.savefig(folder / "elliptical-summits.png", dpi=150)
print(folder / "elliptical-summits.png")
