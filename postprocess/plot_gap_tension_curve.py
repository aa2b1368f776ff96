#!/usr/bin/python3
"""Draws the paper's Fig. 2 from the gap-tension-curve scene: p_hat = P/p0
against c_hat^2 = (c/c_min)^2, as the caption has it. The closed form
(c_hat^2 + 4/sqrt(c_hat))/5 on a fine grid, the paper's linear approximation,
and the FE points (each from the FE stress intensity factors of two unit
loads), with a panel of FE minus closed form below.

Usage: /usr/bin/python3 postprocess/plot_gap_tension_curve.py OUTPUT_DIR
writes OUTPUT_DIR/gap-tension-curve.png"""
import pathlib
import sys

import matplotlib
import numpy

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "gap-tension-curve.csv")
c_hat = numpy.array([row["c_hat"] for row in rows])
fine = numpy.linspace(c_hat.min(), c_hat.max(), 400)

figure, (curve, error) = plt.subplots(2, 1, figsize=(6, 6), sharex=True, gridspec_kw={"height_ratios": [3, 1.2]})
curve.plot(fine**2, (fine**2 + 4 / numpy.sqrt(fine)) / 5, "k-", label=r"closed form $(\hat c^2 + 4/\sqrt{\hat c})/5$")
curve.plot(fine**2, numpy.where(fine**2 > 2.5, fine**2 / 5 + 0.5, 1.0), "k--", label="paper's linear approximation")
curve.plot(c_hat**2, [row["p_hat FE"] for row in rows], "o", mfc="none", color="tab:red", label="FE (J-integral)")
curve.set_ylabel(r"$\hat p = P/p_0$")
curve.set_title("Gap tension against gap size (paper Fig. 2)\n"
                r"$\hat c = c/c_{min}$, both normalised by the closed-form $p_0$ and $c_{min}$", fontsize=10)
curve.legend()
error.plot(c_hat**2, [row["p_hat FE"] - row["p_hat exact"] for row in rows], "o-", color="tab:red", ms=4)
error.axhline(0, color="grey", lw=0.5)
error.ticklabel_format(axis="y", style="sci", scilimits=(0, 0))
error.set_xlabel(r"$\hat c^2$")
error.set_ylabel("FE - closed form")
figure.tight_layout()
figure.savefig(folder / "gap-tension-curve.png", dpi=150)
print(folder / "gap-tension-curve.png")
