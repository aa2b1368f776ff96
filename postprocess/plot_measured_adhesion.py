#!/usr/bin/python3
"""Adhesion on a measured surface: the non-contact area against the mean
pressure of the measured map and of its Gaussian twins at each magnification
(the map low-passed), the adhesive
boundary-element solution in the JKR limit on the loading branch (error bars:
the twins' standard error plus the extrapolation's error) beside the
adhesionless solution at p_bar and at p_bar + p0 (the paper's rule) at the
largest magnification. Reads
measured-adhesion.csv.

Usage: /usr/bin/python3 postprocess/plot_measured_adhesion.py OUTPUT_DIR
writes OUTPUT_DIR/measured-adhesion.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = [row for row in read_table(folder, "measured-adhesion.csv") if row["branch"] == "loading"]

figure, axes = plt.subplots(figsize=(8, 5.5))
zetas = sorted({row["zeta"] for row in rows})
markers = "^sodv"
for surface, colour in (("measured map", "k"), ("Gaussian twins", "b")):
    for index, zeta in enumerate(zetas):
        of = sorted((row for row in rows if row["surface"] == surface and row["zeta"] == zeta),
                    key=lambda row: row["p_bar/sqrtV"])
        if not of:
            continue
        loads = [row["p_bar/sqrtV"] for row in of]
        axes.errorbar(loads, [row["JKR limit"] for row in of],
                      yerr=[2 * row["std error"] + row["extrapolation error"] for row in of],
                      fmt=colour + markers[index % len(markers)] + "-", ms=5, capsize=3,
                      label=f"{surface}, zeta = {zeta:.4g}: adhesive BEM, JKR limit "
                            f"(p0/sqrt(V) = {of[0]['p0/sqrtV']:.3g})")
        if zeta == zetas[-1]:
            axes.plot(loads, [row["adhesionless at p_bar"] for row in of], colour + ":", lw=1.2,
                      label=f"{surface}, zeta = {zeta:.4g}: adhesionless at p_bar")
            axes.plot(loads, [row["adhesionless at p_bar + p0"] for row in of], colour + "--", lw=1.2,
                      label=f"{surface}, zeta = {zeta:.4g}: adhesionless at p_bar + p0 (the paper's rule)")
axes.set_yscale("log")
axes.set_xlabel(r"mean pressure $\bar p/\sqrt{V}$ (dimensionless)")
axes.set_ylabel(r"non-contact area $A_{nc}/A_0$ (dimensionless)")
axes.set_title("Adhesion on a measured surface and its Gaussian twins (loading branch)", fontsize=9)
axes.grid(alpha=0.3, which="both")
axes.legend(fontsize=7)
corner_note(figure, folder)
figure.tight_layout(rect=(0, 0.02, 1, 1))
figure.savefig(folder / "measured-adhesion.png", dpi=120)
