#!/usr/bin/python3
"""Draws the summit statistics of sampled full-contact pressure fields: the
summit density eta and the mean summit curvature 1/R_p with their standard
errors against zeta, each in units of the consistent (Nayak) value, beside the
paper's value and the lattice expectation; and, for the last (H, zeta), the
summit height distribution beside the layer's assumption (eta times the
Gaussian of the field values) and the mean summit curvature against height.
Reads the tables of the summit-statistics scene.

Usage: /usr/bin/python3 postprocess/plot_summit_statistics.py OUTPUT_DIR
writes OUTPUT_DIR/summit-statistics.png"""
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "summit-statistics.csv")
bins = read_table(folder, "summit-heights.csv")

figure, (density, curvature, heights, by_height) = plt.subplots(1, 4, figsize=(17, 4.2))
for k, hurst in enumerate(sorted({row["H"] for row in rows})):
    own = [row for row in rows if row["H"] == hurst]
    zeta = [row["zeta"] for row in own]
    for axes, name in ((density, "eta"), (curvature, "1/R_p")):
        unit = [row[f"{name} consistent (1/m^2)" if name == "eta" else f"{name} consistent (Pa/m^2)"]
                for row in own]
        suffix = " (1/m^2)" if name == "eta" else " (Pa/m^2)"
        line = axes.errorbar(zeta, [row[name + " sampled" + suffix] / u for row, u in zip(own, unit)],
                             [row[name + " std error" + suffix] / u for row, u in zip(own, unit)], fmt="o",
                             capsize=3, label=f"sampled, H = {hurst:g}")
        color = line[0].get_color()
        axes.plot(zeta, [row[name + " lattice Kac-Rice" + suffix] / u for row, u in zip(own, unit)], "x",
                  color=color, label=f"lattice Kac-Rice, H = {hurst:g}")
        axes.plot(zeta, [row[name + " paper" + suffix] / u for row, u in zip(own, unit)], "s--", mfc="none",
                  color=color, label=f"paper, H = {hurst:g}")
for axes, title in ((density, r"summit density $\eta/\eta_{\rm Nayak}$"),
                    (curvature, r"mean summit curvature $R_{p,\rm Nayak}/R_p$")):
    axes.axhline(1, color="k", lw=0.8, label="consistent (Nayak)")
    axes.set_xscale("log")
    axes.set_xlabel(r"magnification $\zeta$")
    axes.set_title(title, fontsize=10)
    axes.legend(fontsize=6)

last = (rows[-1]["H"], rows[-1]["zeta"])
own = [row for row in bins if (row["H"], row["zeta"]) == last]
centre = [(row["z low/sqrtV"] + row["z high/sqrtV"]) / 2 for row in own]
scale = max(row["density Kac-Rice at bin centre (1/(m^2 Pa))"] for row in own)
heights.errorbar(centre, [row["density per height (1/(m^2 Pa))"] / scale for row in own],
                 [row["density std error (1/(m^2 Pa))"] / scale for row in own], fmt="o", capsize=3,
                 label="summit heights, sampled")
heights.plot(centre, [row["density Kac-Rice at bin centre (1/(m^2 Pa))"] / scale for row in own], "-",
             label="Kac-Rice (lattice moments)")
last_row = rows[-1]
sqrt_V = math.sqrt(last_row["V consistent (Pa^2)"])
heights.plot(centre, [last_row["eta consistent (1/m^2)"] * math.exp(-z * z / 2) / math.sqrt(2 * math.pi) / sqrt_V / scale
                      for z in centre], "--", label=r"layer's assumption $\eta\,\phi_V(z)$")
heights.set_xlabel(r"summit height $z/\sqrt{V}$")
heights.set_ylabel("summits per area and height (scaled)")
heights.set_title(f"H = {last[0]:g}, zeta = {last[1]:g}", fontsize=10)
heights.legend(fontsize=7, loc="upper left")
kappa = last_row["1/R_p consistent (Pa/m^2)"]
filled = [row for row in own if row["mean curvature (Pa/m^2)"] != ""]
by_height.errorbar([(row["z low/sqrtV"] + row["z high/sqrtV"]) / 2 for row in filled],
                   [row["mean curvature (Pa/m^2)"] / kappa for row in filled],
                   [row["mean curvature std error (Pa/m^2)"] / kappa for row in filled], fmt="o", capsize=3,
                   label="sampled")
by_height.plot(centre, [row["mean curvature Kac-Rice at bin centre (Pa/m^2)"] / kappa for row in own], "-",
               label="Kac-Rice (lattice moments)")
by_height.axhline(1, color="k", lw=0.8, label="consistent mean (one R_p for all)")
by_height.set_xlabel(r"summit height $z/\sqrt{V}$")
by_height.set_ylabel(r"mean summit curvature $\kappa/\kappa_{\rm Nayak}$")
by_height.set_title(f"H = {last[0]:g}, zeta = {last[1]:g}", fontsize=10)
by_height.legend(fontsize=7)
figure.tight_layout()
figure.savefig(folder / "summit-statistics.png", dpi=150)
print(folder / "summit-statistics.png")
