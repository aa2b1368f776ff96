#!/usr/bin/python3
"""The adhesive sphere (JKR): left, the load F/(pi w R) against the contact
radius (over the radius at pull-off) along the unloading path, the
boundary-element solution beside JKR's F(a), with JKR's pull-off -3/2 and the solver's pull-off in the JKR limit
(band: its error estimate); right, the pull-off at each cohesive zone
l_pz/a and period L/a on log axes, converging onto that limit. Reads
jkr-sphere-unloading.csv, jkr-sphere-pull-off.csv and jkr-sphere-summary.csv.

Usage: /usr/bin/python3 postprocess/plot_jkr_sphere.py OUTPUT_DIR
writes OUTPUT_DIR/jkr-sphere.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
path = sorted(read_table(folder, "jkr-sphere-unloading.csv"), key=lambda row: row["contact radius/a"])
pull_offs = read_table(folder, "jkr-sphere-pull-off.csv")
summary = {row["quantity"]: row["value"] for row in read_table(folder, "jkr-sphere-summary.csv")}
limit, error = summary["JKR-limit pull-off F/(pi w R)"], summary["error estimate"]

figure, (unloading, zones) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": [3, 2]})
# JKR in these units (a: the contact radius at pull-off): F/(pi w R) = (3/2) r^3 - 3 r^(3/2), r = radius/a.
radius = [row["contact radius/a"] for row in path]
for low, high, style, name in ((0.5, 1, "k:", "JKR's F(a), unstable under load control"),
                               (1, max(radius) * 1.02, "k-", "JKR's F(a)")):
    r = np.linspace(low, high, 200)
    unloading.plot(r, 1.5 * r ** 3 - 3 * r ** 1.5, style, lw=1, label=name)
unloading.plot(radius, [row["F/(pi w R)"] for row in path], "ro", ms=4,
               label="boundary elements, finest cohesive zone")
finest = min(pull_offs, key=lambda row: row["l_pz/a"])
unloading.plot([finest["contact radius/a"]], [finest["F/(pi w R)"]], "r^", ms=7,
               label=f"boundary elements' pull-off at l_pz/a = {finest['l_pz/a']:g}")
for axes in (unloading, zones):
    axes.axhline(-1.5, color="k", ls="--", lw=1, label="JKR's pull-off -3/2")
    axes.axhspan(limit - error, limit + error, color="tab:red", alpha=0.15,
                 label=f"pull-off in the JKR limit, {limit:.4f} +- {error:.2g}")
unloading.set_xlabel("contact radius / a (dimensionless)")
unloading.set_ylabel(r"load $F/(\pi w R)$ (dimensionless; negative: tension)")
unloading.set_title("Unloading an adhesive sphere: the full solution beside JKR", fontsize=9)
unloading.grid(alpha=0.3)
unloading.legend(fontsize=7)
for period in sorted({row["L/a"] for row in pull_offs}):
    of_period = sorted((row for row in pull_offs if row["L/a"] == period), key=lambda row: row["l_pz/a"])
    zones.plot([row["l_pz/a"] for row in of_period], [row["F/(pi w R)"] for row in of_period], "o-", ms=4,
               label=f"pull-off, period L/a = {period:g}")
zones.set_xscale("log")
zones.set_xlabel(r"cohesive zone $l_{pz}/a$ (dimensionless)")
zones.set_ylabel(r"pull-off $F/(\pi w R)$ (dimensionless)")
zones.set_title("the pull-off at each zone and period, onto the JKR limit", fontsize=9)
zones.grid(alpha=0.3, which="both")
zones.legend(fontsize=7)
corner_note(figure, folder)
figure.tight_layout(rect=(0, 0.02, 1, 1))
figure.savefig(folder / "jkr-sphere.png", dpi=150)
print(folder / "jkr-sphere.png")
