#!/usr/bin/python3
"""Draws the paper's Figs. 4 and 5 from the area-load scene, one column per
Hurst exponent, one colour per magnification zeta; the title states the
normalisation convention of the run.

Fig. 4: the non-contact area A_nc/A_0 against p_bar/sqrt(V), on a linear and
on a log scale (the H = 0.75 curves vanish on the linear one): the paper's
linear gap law (solid), the exact gap function g (dashed) and no adhesion
(black, dotted). Where a law gives A_nc/A_0 > 1 (negative loads; flagged in
area-load.csv) it is no area fraction, and is not drawn.
Fig. 5: the real contact area of the paper's alternative derivation,
A_c/A_0 = erf((p_bar + p0)/sqrt(2V)) (solid), beside 1 - A_nc/A_0 of the
linear law of Fig. 4 (thin, dashed): the two derivations differ, and the
figure shows by how much.

Usage: /usr/bin/python3 postprocess/plot_area_load.py OUTPUT_DIR
writes OUTPUT_DIR/area-load-fig4.png and OUTPUT_DIR/area-load-fig5.png"""
import pathlib
import sys
from collections import defaultdict

import matplotlib
import numpy

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import convention_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
curves = defaultdict(list)  # (H, zeta) -> rows
for row in read_table(folder, "area-load.csv"):
    curves[(row["H"], row["zeta"])].append(row)
hursts = sorted({hurst for hurst, _ in curves}, reverse=True)
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]


def drawn(rows, column, flag=None):
    """Loads and values of `column`, NaN where `flag` marks A_nc/A_0 > 1."""
    values = [numpy.nan if flag and row[flag] else row[column] for row in rows]
    return [row["p_bar/sqrtV"] for row in rows], values


def coinciding_note(axes, hurst):
    """theta = 0 at H = 1/2: p0/sqrt(V) = 1 for every zeta, one curve for all."""
    adhesions = {rows[0]["p0/sqrtV"] for (h, _), rows in curves.items() if h == hurst}
    if len(adhesions) == 1 and len([key for key in curves if key[0] == hurst]) > 1:
        axes.text(0.03, 0.05, "theta = 0: every zeta gives\nthe same curve (they coincide)",
                  transform=axes.transAxes, fontsize=8)


# Fig. 4: linear scale above, log scale below.
figure, panels = plt.subplots(2, len(hursts), figsize=(4.2 * len(hursts), 7.5), squeeze=False)
for column, hurst in enumerate(hursts):
    for scale, axes in zip(("linear", "log"), panels[:, column]):
        for k, ((h, zeta), rows) in enumerate(sorted(item for item in curves.items() if item[0][0] == hurst)):
            colour = colours[k % len(colours)]
            axes.plot(*drawn(rows, "A_nc linear closed form", "A_nc linear > 1"), "-", color=colour,
                      label=rf"$\zeta$ = {zeta:g}")
            axes.plot(*drawn(rows, "A_nc exact g", "A_nc exact g > 1"), "--", color=colour, lw=1)
        axes.plot(*drawn(rows, "A_nc adhesionless", "A_nc adhesionless > 1"), "k:", label="no adhesion")
        axes.set_yscale(scale)
        if scale == "log":
            axes.set_ylim(1e-12, 1.5)
        axes.set_xlabel(r"$\bar p/\sqrt{V}$")
        axes.set_ylabel(r"$A_{nc}/A_0$")
        axes.set_title(f"H = {hurst:g}, {scale} scale", fontsize=10)
    coinciding_note(panels[0, column], hurst)
panels[0, 0].plot([], [], "k-", label="linear gap law")
panels[0, 0].plot([], [], "k--", lw=1, label="exact g")
panels[0, 0].legend(fontsize="small")
figure.suptitle("Non-contact area (paper Fig. 4); " + convention_note(folder), fontsize=10)
figure.tight_layout()
figure.savefig(folder / "area-load-fig4.png", dpi=130)
print(folder / "area-load-fig4.png")

# Fig. 5: the erf form, and 1 - A_nc of the linear law for comparison.
figure, panels = plt.subplots(1, len(hursts), figsize=(4.2 * len(hursts), 4), squeeze=False)
for axes, hurst in zip(panels[0], hursts):
    for k, ((h, zeta), rows) in enumerate(sorted(item for item in curves.items() if item[0][0] == hurst)):
        colour = colours[k % len(colours)]
        axes.plot(*drawn(rows, "A_c Persson-type"), "-", color=colour, label=rf"$\zeta$ = {zeta:g}")
        loads, linear = drawn(rows, "A_nc linear closed form", "A_nc linear > 1")
        axes.plot(loads, 1 - numpy.array(linear), "--", color=colour, lw=0.8)
    axes.plot(*drawn(rows, "A_c Persson-type adhesionless"), "k:", label="no adhesion")
    coinciding_note(axes, hurst)
    axes.set_xlabel(r"$\bar p/\sqrt{V}$")
    axes.set_ylabel(r"$A_c/A_0$")
    axes.set_title(f"H = {hurst:g}", fontsize=10)
panels[0][0].plot([], [], "k-", label=r"erf$((\bar p + p_0)/\sqrt{2V})$")
panels[0][0].plot([], [], "k--", lw=0.8, label=r"$1 - A_{nc}/A_0$, linear law (Fig. 4)")
panels[0][0].legend(fontsize="small")
figure.suptitle(r"Real contact area (paper Fig. 5): $A_c/A_0 = $ erf$((\bar p + p_0)/\sqrt{2V})$, the paper's "
                "alternative derivation, beside 1 - A_nc of Fig. 4\n" + convention_note(folder), fontsize=10)
figure.tight_layout()
figure.savefig(folder / "area-load-fig5.png", dpi=130)
print(folder / "area-load-fig5.png")
