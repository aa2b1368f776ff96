#!/usr/bin/python3
"""Draws the convergence of the FFT boundary-element solver on Westergaard's
sinusoid: the error of the contact half-width (sub-grid and from the contact
points alone) and of the pressure inside the strip against the grid points per
wavelength, one line per load p_bar/p*. Reads bem-westergaard.csv.

Usage: /usr/bin/python3 postprocess/plot_bem_westergaard.py OUTPUT_DIR
writes OUTPUT_DIR/bem-westergaard.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "bem-westergaard.csv")
figure, (width, pressure) = plt.subplots(1, 2, figsize=(10, 4.2))
for load in sorted({row["p_bar/p*"] for row in rows}):
    own = [row for row in rows if row["p_bar/p*"] == load]
    n = [row["points per lambda"] for row in own]
    line, = width.loglog(n, [row["|a error|/lambda"] for row in own], "o-", label=rf"sub-grid, $\bar p/p^* = {load:g}$")
    width.loglog(n, [row["|a error|/lambda contact points"] for row in own], "s:", mfc="none",
                 color=line.get_color(), label=rf"contact points, $\bar p/p^* = {load:g}$")
    pressure.loglog(n, [row["max |p error|/p* inside"] for row in own], "o-", label=rf"$\bar p/p^* = {load:g}$")
width.axhline(1e-3, color="grey", lw=0.6)
width.set_xlabel(r"grid points per wavelength $\lambda/\Delta x$")
width.set_ylabel(r"$|a - a_{\rm W}|/\lambda$")
width.set_title("contact half-width", fontsize=10)
width.legend(fontsize=6)
pressure.set_xlabel(r"grid points per wavelength $\lambda/\Delta x$")
pressure.set_ylabel(r"max $|p - p_{\rm W}|/p^*$, more than $0.05\lambda$ inside the edges")
pressure.set_title("contact pressure", fontsize=10)
pressure.legend(fontsize=7)
figure.tight_layout()
figure.savefig(folder / "bem-westergaard.png", dpi=150)
print(folder / "bem-westergaard.png")
