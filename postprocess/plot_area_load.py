#!/usr/bin/python3
"""Draws the paper's Figs. 4 and 5 from the area-load scene: one panel per
Hurst exponent, one curve per magnification zeta, the adhesionless curve dashed.
Fig. 4: non-contact area A_nc/A_0 (linear law) against p_bar/sqrt(V) >= 0.
Fig. 5: real contact area A_c/A_0 = erf((p_bar + p0)/sqrt(2V)), all loads.

Usage: /usr/bin/python3 postprocess/plot_area_load.py OUTPUT_DIR
writes OUTPUT_DIR/area-load-fig4.png and OUTPUT_DIR/area-load-fig5.png"""
import csv
import pathlib
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = pathlib.Path(sys.argv[1])
curves = defaultdict(list)  # (H, zeta) -> rows
with open(folder / "area-load.csv") as table:
    for row in csv.DictReader(table):
        row = {key: float(value) for key, value in row.items()}
        curves[(row["H"], row["zeta"])].append(row)
hursts = sorted({hurst for hurst, _ in curves}, reverse=True)

figures = {
    "fig4": ("A_nc linear closed form", "A_nc adhesionless", r"$A_{nc}/A_0$", "Non-contact area (paper Fig. 4)", 0.0),
    "fig5": ("A_c Persson-type", "A_c Persson-type adhesionless", r"$A_c/A_0$", "Real contact area (paper Fig. 5)", None),
}
for name, (column, reference, label, title, smallest_load) in figures.items():
    figure, panels = plt.subplots(1, len(hursts), figsize=(4 * len(hursts), 3.8), squeeze=False)
    for axes, hurst in zip(panels[0], hursts):
        for (h, zeta), rows in sorted(curves.items()):
            if h != hurst:
                continue
            shown = [row for row in rows if smallest_load is None or row["p_bar/sqrtV"] >= smallest_load]
            loads = [row["p_bar/sqrtV"] for row in shown]
            axes.plot(loads, [row[column] for row in shown], label=rf"$\zeta$ = {zeta:g}")
        axes.plot(loads, [row[reference] for row in shown], "k--", label="no adhesion")
        axes.set_title(f"H = {hurst:g}")
        axes.set_xlabel(r"$\bar p/\sqrt{V}$")
        axes.set_ylabel(label)
    panels[0][0].legend(fontsize="small")
    figure.suptitle(title)
    figure.tight_layout()
    figure.savefig(folder / f"area-load-{name}.png", dpi=150)
    print(folder / f"area-load-{name}.png")
