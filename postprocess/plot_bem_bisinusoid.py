#!/usr/bin/python3
"""The closure of the adhesive bi-sinusoid against Johnson's parameter alpha:
the load margin 1 - p_bar/p* below full contact at which the last gap closes,
on log axes, beside the paper's isolated-gap asymptote
psi (2 pi)^(2/5) alpha^(4/5). Markers: the FE penny gap's p0/p*, the
boundary-element solution at each cohesive zone and its JKR limit (error bar:
the extrapolation's estimate); on the right each over the asymptote. Reads
bem-bisinusoid-closure.csv.

Usage: /usr/bin/python3 postprocess/plot_bem_bisinusoid.py OUTPUT_DIR
writes OUTPUT_DIR/bem-bisinusoid.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "bem-bisinusoid-closure.csv")
alpha = [row["alpha"] for row in rows]
zones = [column for column in rows[0] if column.startswith("BEM l_pz/c_min=")]
figure, (axes, ratio) = plt.subplots(1, 2, figsize=(11, 4.8), gridspec_kw={"width_ratios": [3, 2]})
line = np.geomspace(min(alpha) / 2, max(alpha) * 2, 100)
psi = 1.2020809449045589
axes.plot(line, psi * (2 * np.pi) ** 0.4 * line ** 0.8, "k-", lw=1,
          label=r"the paper's isolated gap: $\psi (2\pi)^{2/5} \alpha^{4/5}$")
axes.plot(alpha, [row["FE p0/p*"] for row in rows], "gs", mfc="none", ms=9, label="FE penny gap, p0/p*")
for zone, marker in zip(zones, "v^<>12348"):
    axes.plot(alpha, [row[zone] for row in rows], marker, color="0.5", label=zone.replace("BEM ", "BEM, "))
axes.errorbar(alpha, [row["JKR limit"] for row in rows], [row["error estimate"] for row in rows], fmt="ro",
              capsize=3, label="BEM, JKR limit (extrapolated)")
axes.set_xscale("log")
axes.set_yscale("log")
axes.set_xlabel(r"Johnson's parameter $\alpha$ (dimensionless)")
axes.set_ylabel(r"closure margin $1 - \bar p/p^*$ (dimensionless)")
axes.set_title("Bi-sinusoid with adhesion: the load at which the last gap closes", fontsize=9)
axes.grid(alpha=0.3, which="both")
axes.legend(fontsize=7)
# Right: each over the asymptote, where the differences show.
asymptote = [row["isolated psi (2 pi)^(2/5) alpha^(4/5)"] for row in rows]
ratio.axhline(1, color="k", lw=1)
ratio.plot(alpha, [row["FE p0/p*"] / a for row, a in zip(rows, asymptote)], "gs", mfc="none", ms=9)
for zone, marker in zip(zones, "v^<>12348"):
    ratio.plot(alpha, [row[zone] / a for row, a in zip(rows, asymptote)], marker, color="0.5")
ratio.errorbar(alpha, [row["JKR limit"] / a for row, a in zip(rows, asymptote)],
               [row["error estimate"] / a for row, a in zip(rows, asymptote)], fmt="ro", capsize=3)
ratio.set_xscale("log")
ratio.set_xlabel(r"$\alpha$ (dimensionless)")
ratio.set_ylabel("over the paper's asymptote (dimensionless)")
ratio.grid(alpha=0.3, which="both")
corner_note(figure, folder)
figure.tight_layout(rect=(0, 0.02, 1, 1))
figure.savefig(folder / "bem-bisinusoid.png", dpi=150)
print(folder / "bem-bisinusoid.png")
