#!/usr/bin/python3
"""Draws the paper's Fig. 1 from FE: Johnson's adhesive 1D sinusoid, p_bar/p*
against the contact half-width a/lambda, FE points (roots of K_I = K_Ic of the
periodic gap model) over the closed-form curves, one symbol per alpha, with
the closed form's jump into contact (maximum) and pull-off (minimum) marked.
Reads the tables of the johnson-curves scene.

Usage: /usr/bin/python3 postprocess/plot_johnson_curves.py OUTPUT_DIR
writes OUTPUT_DIR/johnson-curves.png"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(name):
    with open(folder / name) as table:
        return [{key: float(value) for key, value in row.items()} for row in csv.DictReader(table)]


folder = pathlib.Path(sys.argv[1])
points = read("johnson-curves.csv")
curves = read("johnson-closed-form.csv")
extremes = read("johnson-extremes.csv")

symbols = "osD^vp*"
figure, axes = plt.subplots(figsize=(6.5, 4.8))
alphas = sorted({row["alpha"] for row in points})
for k, alpha in enumerate(alphas):
    column = next(name for name in curves[0] if name.startswith("p_bar/p* alpha=") and float(name.split("=")[1]) == alpha)
    line, = axes.plot([row["a/lambda"] for row in curves], [row[column] for row in curves], "-", lw=1)
    fe = [row for row in points if row["alpha"] == alpha]
    axes.plot([row["a/lambda"] for row in fe], [row["p_bar/p* FE"] for row in fe], symbols[k % len(symbols)],
              mfc="none", color=line.get_color(), label=rf"$\alpha = {alpha:g}$")
# Without adhesion the "extremes" are the ends of the curve; only alpha > 0 is marked.
for k, row in enumerate(row for row in extremes if row["alpha"] > 0):
    axes.plot(row["jump into contact a/lambda"], row["jump into contact p_bar/p*"], "k^", ms=7,
              label="jump into contact (max)" if k == 0 else None)
    axes.plot(row["pull-off a/lambda"], row["pull-off p_bar/p*"], "kv", ms=7,
              label="pull-off (min)" if k == 0 else None)
axes.axhline(0, color="grey", lw=0.5)
axes.set_xlim(0, 0.5)
axes.set_ylim(-1, 1.1)
axes.set_xlabel(r"contact half-width $a/\lambda$")
axes.set_ylabel(r"mean pressure $\bar p / p^*$ (compressive > 0)")
axes.set_title("Johnson's adhesive sinusoid from FE (paper Fig. 1)")
axes.text(0.01, -0.97,
          r"lines: $\bar p/p^* = \sin^2(\pi a/\lambda) - \alpha\sqrt{\tan(\pi a/\lambda)}$;"
          "  symbols: FE, $K_I = K_{Ic}$\n"
          r"$\alpha = K_{Ic}/(p^*\sqrt{\lambda})$, $p^* = \pi E^* h/\lambda$; markers: extremes of the closed form",
          fontsize=7, va="bottom")
axes.legend(fontsize=8, loc="upper left")
figure.tight_layout()
figure.savefig(folder / "johnson-curves.png", dpi=150)
print(folder / "johnson-curves.png")
