#!/usr/bin/python3
"""Johnson's adhesive sinusoid: the mean pressure p_bar/p* against the
contact half-width a/lambda, Johnson's closed form
p_bar/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda)) for each alpha
(lines), the FE periodic gap and the boundary-element solution in the JKR
limit (markers; the last a/lambda of each alpha is the jump into full
contact, the maximum of the curve). Right: |BEM - Johnson| at each cohesive
zone l_pz/lambda on log axes, converging onto the JKR limit's (drawn at half
the finest zone, its error estimate as a bar). Reads bem-johnson.csv.

Usage: /usr/bin/python3 postprocess/plot_bem_johnson.py OUTPUT_DIR
writes OUTPUT_DIR/bem-johnson.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "bem-johnson.csv")
zones = [column for column in rows[0] if column.startswith("BEM l_pz/lambda=")]
lengths = [float(column.split("=")[1]) for column in zones]
alphas = sorted({row["alpha"] for row in rows})
colours = dict(zip(alphas, plt.rcParams["axes.prop_cycle"].by_key()["color"]))
figure, (curve, error) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": [3, 2]})
a = np.linspace(0.005, 0.495, 400)
for alpha in alphas:
    of_alpha = sorted((row for row in rows if row["alpha"] == alpha), key=lambda row: row["a/lambda"])
    colour = colours[alpha]
    curve.plot(a, np.sin(np.pi * a) ** 2 - alpha * np.sqrt(np.tan(np.pi * a)), "-", color=colour, lw=1,
               label=f"Johnson's closed form, alpha = {alpha:g}")
    width = [row["a/lambda"] for row in of_alpha]
    curve.plot(width, [row["FE"] for row in of_alpha], "s", color=colour, mfc="none", ms=9)
    curve.errorbar(width, [row["BEM JKR limit"] for row in of_alpha], [row["error estimate"] for row in of_alpha],
                   fmt="o", color=colour, ms=4)
    curve.plot(width[-1:], [of_alpha[-1]["BEM JKR limit"]], "*", color=colour, ms=14, mfc="none")
    for row in of_alpha:
        error.loglog(lengths, [abs(row[zone] - row["Johnson"]) for zone in zones], "-", color=colour, lw=0.8,
                     alpha=0.7)
        error.errorbar([lengths[-1] / 2], [row["|BEM - Johnson|"]], [[0], [row["error estimate"]]], fmt="o",
                       color=colour, ms=4)
curve.plot([], [], "ks", mfc="none", ms=9, label="FE periodic gap")
curve.plot([], [], "ko", ms=4, label="BEM, JKR limit (bar: its error estimate)")
curve.plot([], [], "k*", mfc="none", ms=14, label="jump into full contact (the maximum)")
curve.set_ylim(min(row["Johnson"] for row in rows) - 0.1, 1.02)
curve.set_xlabel(r"contact half-width $a/\lambda$ (dimensionless)")
curve.set_ylabel(r"mean pressure $\bar p/p^*$ (dimensionless)")
curve.set_title("Johnson's sinusoid with adhesion: the full solution on the closed form", fontsize=9)
curve.grid(alpha=0.3)
curve.legend(fontsize=7)
error.set_xlabel(r"cohesive zone $l_{pz}/\lambda$ (dimensionless)")
error.set_ylabel(r"$|\bar p_{BEM} - \bar p_{Johnson}|/p^*$ (dimensionless)")
error.set_title("each a/lambda, by alpha (colour); the JKR limit at half the finest zone", fontsize=9)
error.grid(alpha=0.3, which="both")
corner_note(figure, folder)
figure.tight_layout(rect=(0, 0.02, 1, 1))
figure.savefig(folder / "bem-johnson.png", dpi=150)
print(folder / "bem-johnson.png")
