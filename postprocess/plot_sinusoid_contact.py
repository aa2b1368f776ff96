#!/usr/bin/python3
"""Draws the paper's Fig. 1, Johnson's adhesive 1D sinusoid: p/p* against the
contact semi-width a/lambda for each alpha, from the sinusoid-contact scene.

Usage: /usr/bin/python3 postprocess/plot_sinusoid_contact.py OUTPUT_DIR
writes OUTPUT_DIR/sinusoid-contact.png"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = pathlib.Path(sys.argv[1])
with open(folder / "sinusoid-contact.csv") as table:
    reader = csv.reader(table)
    header = next(reader)
    rows = [[float(value) for value in row] for row in reader]

figure, axes = plt.subplots(figsize=(5.5, 4))
for column, name in enumerate(header[1:], start=1):
    axes.plot([row[0] for row in rows], [row[column] for row in rows], label=name.replace("p/p* ", ""))
axes.axhline(0, color="grey", lw=0.5)
axes.set_ylim(-1, 1.1)
axes.set_xlabel(r"$a/\lambda$")
axes.set_ylabel(r"$\bar p / p^*$")
axes.set_title("Johnson's adhesive sinusoid (paper Fig. 1)")
axes.legend()
figure.tight_layout()
figure.savefig(folder / "sinusoid-contact.png", dpi=150)
print(folder / "sinusoid-contact.png")
