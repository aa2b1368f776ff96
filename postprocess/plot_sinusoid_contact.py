#!/usr/bin/python3
"""Draws the paper's Fig. 1 from the sinusoid-contact scene: Johnson's
adhesive 1D sinusoid, p_bar/p* = sin^2(pi a/lambda) - alpha sqrt(tan(pi a/lambda))
against the contact semi-width a/lambda, one curve per alpha, with its
extremes marked: the maximum is the jump into full contact, the minimum the
pull-off load. Closed form (no FE).

Usage: /usr/bin/python3 postprocess/plot_sinusoid_contact.py OUTPUT_DIR
writes OUTPUT_DIR/sinusoid-contact.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "sinusoid-contact.csv")
a = [row["a/lambda"] for row in rows]
figure, axes = plt.subplots(figsize=(6.5, 4.6))
for column in [key for key in rows[0] if key.startswith("p/p* alpha=")]:
    alpha = float(column.split("=")[1])
    load = [row[column] for row in rows]
    (line,) = axes.plot(a, load, label=rf"$\alpha$ = {alpha:g}")
    if alpha == 0:
        continue
    # Interior extremes on the grid: the maximum is the jump into contact, the minimum the pull-off.
    interior = range(1, len(load) - 1)
    for marker, is_extreme in (("^", lambda i: load[i] >= max(load[i - 1], load[i + 1])),
                               ("v", lambda i: load[i] <= min(load[i - 1], load[i + 1]))):
        for i in [i for i in interior if is_extreme(i)][:1]:
            axes.plot(a[i], load[i], marker, color=line.get_color(), ms=7)
axes.plot([], [], "k^", label="jump into full contact (max)")
axes.plot([], [], "kv", label="pull-off (min)")
axes.axhline(0, color="grey", lw=0.5)
axes.set_ylim(-1, 1.1)
axes.set_xlabel(r"$a/\lambda$")
axes.set_ylabel(r"$\bar p / p^*$")
axes.set_title("Johnson's adhesive sinusoid (paper Fig. 1), closed form\n"
               r"$\bar p/p^* = \sin^2(\pi a/\lambda) - \alpha \sqrt{\tan(\pi a/\lambda)}$", fontsize=10)
axes.legend(fontsize="small", loc="lower right")
figure.tight_layout()
figure.savefig(folder / "sinusoid-contact.png", dpi=150)
print(folder / "sinusoid-contact.png")
