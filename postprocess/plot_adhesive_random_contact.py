#!/usr/bin/python3
"""The paper's Figs. 4 and 3 redrawn with the full solution beside them.

Fig. 4 (adhesive-random-contact-fig4.png, where the run has several loads,
or no Fig. 3):
the non-contact area A_nc/A_0 against the mean pressure p_bar/sqrt(V) with
adhesion, one panel per Hurst exponent H. Lines: the paper's law (its linear
gap law summed over the summits, in the paper's and the consistent
convention), the same layer with the exact gap branch g, and the isolated-gap
law over the realisations' own summits. Markers, one shape per magnification
zeta: the adhesive boundary-element solution in the JKR limit (loading branch
filled, switched-on branch open) and the adhesionless one at p_bar and at
p_bar + p0 (which the paper says the adhesive one equals).

Fig. 3 (adhesive-random-contact-fig3.png, where the run has several
adhesions at zero load): A_nc(0)/A_0 against p0/sqrt(V): the paper's curve
exp(-x^2/2) - x sqrt(pi/2) erfc(x/sqrt 2) (paper convention), the layer in
the consistent convention with the linear law, the p0/2 fit and the exact g,
and the adhesive BEM at zero load (loading branch), one marker per zeta.

Fig. 4 on log axes, Fig. 3 on linear ones (as the paper's: full contact is
zero). Error bars: two standard errors over realisations plus the
extrapolation error, cut at 5 % of the value. Reads adhesive-random-contact.csv.

Usage: /usr/bin/python3 postprocess/plot_adhesive_random_contact.py OUTPUT_DIR
writes OUTPUT_DIR/adhesive-random-contact-fig4.png and/or -fig3.png"""
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
rows = read_table(folder, "adhesive-random-contact.csv")
hursts = sorted({row["H"] for row in rows})
zetas = sorted({row["zeta"] for row in rows})
markers = dict(zip(zetas, "osD^vp*"))


def bem(axes, of_branch, x, marker, fill, label):
    """The adhesive BEM's JKR limits with their error bars."""
    value = [row["BEM JKR limit"] for row in of_branch]
    bar = [2 * row["std error"] + row["extrapolation error"] for row in of_branch]
    axes.errorbar(x, value, [[min(b, 0.95 * v) for b, v in zip(bar, value)], bar], fmt=marker,
                  color="tab:red", mfc=fill, capsize=2, label=label)


def figure_4():
    figure, panels = plt.subplots(1, len(hursts), figsize=(5 * len(hursts) + 2.5, 4.6), sharey=True,
                                  squeeze=False)
    for axes, hurst in zip(panels[0], hursts):
        for zeta in zetas:
            of_case = [row for row in rows if row["H"] == hurst and row["zeta"] == zeta]
            loading = [row for row in of_case if row["branch"] == "loading"]
            load = [row["p_bar/sqrtV"] for row in loading]
            label = f"zeta = {zeta:g}"
            first = zeta == zetas[0]
            for column, style, name in (("layer linear paper", "k--", "paper's law, paper convention"),
                                        ("layer linear consistent", "k-", "paper's law, consistent convention"),
                                        ("layer exact g consistent", "g-", "layer with the exact g, consistent"),
                                        ("isolated gaps sampled summits", "m-.", "isolated gaps, sampled summits")):
                axes.plot(load, [row[column] for row in loading], style, lw=0.8, alpha=0.8,
                          label=name if first else None)
            axes.plot(load, [row["adhesionless BEM"] for row in loading], markers[zeta], color="0.6", mfc="none",
                      label=f"BEM without adhesion at p_bar, {label}")
            axes.plot(load, [row["adhesionless BEM at p_bar + p0"] for row in loading], markers[zeta],
                      color="tab:blue", mfc="none", label=f"BEM without adhesion at p_bar + p0, {label}")
            for branch, fill in (("loading", None), ("switched on", "none")):
                of_branch = [row for row in of_case if row["branch"] == branch]
                bem(axes, of_branch, [row["p_bar/sqrtV"] for row in of_branch], markers[zeta], fill,
                    f"adhesive BEM, JKR limit, {branch}, {label}")
        p0 = list(dict.fromkeys(f"{row['p0/sqrtV']:.2f}" for row in sorted(rows, key=lambda row: row["zeta"])
                                if row["H"] == hurst))
        axes.set_title(f"H = {hurst:g}, p0/sqrt(V) = {', '.join(p0)} (by zeta)", fontsize=9)
        axes.set_yscale("log")
        axes.set_ylim(1e-6, 2)
        axes.set_xlabel(r"mean pressure $\bar p/\sqrt{V}$ (dimensionless)")
        axes.grid(alpha=0.3)
    panels[0][0].set_ylabel(r"non-contact area $A_{nc}/A_0$ (dimensionless)")
    panels[0][-1].legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.02, 1))
    figure.suptitle("The paper's Fig. 4 with adhesion (fixed w) beside the full solution", fontsize=10)
    return figure


def figure_3():
    zero = [row for row in rows if row["p_bar/sqrtV"] == 0 and row["branch"] == "loading"]
    figure, panels = plt.subplots(1, len(hursts), figsize=(5.5 * len(hursts) + 2.5, 4.6), sharey=True,
                                  squeeze=False)
    x = np.linspace(0, max(row["p0/sqrtV"] for row in zero) * 1.1, 200)
    paper = [math.exp(-t * t / 2) - t * math.sqrt(math.pi / 2) * math.erfc(t / math.sqrt(2)) for t in x]
    for axes, hurst in zip(panels[0], hursts):
        axes.plot(x, paper, "k--", lw=1, label="the paper's Fig. 3 (linear law, paper convention)")
        for zeta in zetas:
            of_case = sorted((row for row in zero if row["H"] == hurst and row["zeta"] == zeta),
                             key=lambda row: row["p0/sqrtV"])
            p0 = [row["p0/sqrtV"] for row in of_case]
            first = zeta == zetas[0]
            for column, style, name in (("layer linear consistent", "k-", "linear law, consistent convention"),
                                        ("layer p0/2 fit consistent", "c-", "p0/2 fit, consistent convention"),
                                        ("layer exact g consistent", "g-", "exact g, consistent convention")):
                if column not in rows[0]:  # a table of a run from before the fit was added
                    continue
                axes.plot(p0, [row[column] for row in of_case], style, lw=0.8, alpha=0.8,
                          label=f"layer: {name}" if first else None)
            bem(axes, of_case, p0, markers[zeta], None, f"adhesive BEM at zero load, JKR limit, zeta = {zeta:g}")
        axes.set_ylim(-0.02, 1.05)
        axes.set_title(f"H = {hurst:g}", fontsize=9)
        axes.set_xlabel(r"adhesion $p_0/\sqrt{V}$ (dimensionless)")
        axes.grid(alpha=0.3)
    panels[0][0].set_ylabel(r"non-contact area at zero load $A_{nc}(0)/A_0$ (dimensionless)")
    panels[0][-1].legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.02, 1))
    figure.suptitle("The paper's Fig. 3 beside the full solution at zero load", fontsize=10)
    return figure


# Fig. 3 where there are several adhesions at zero load; Fig. 4 where there are several loads, or no Fig. 3.
several_adhesions = len({row["p0/sqrtV"] for row in rows if row["p_bar/sqrtV"] == 0 and row["zeta"] == zetas[0]}) > 1
drawn = [(figure_3(), "adhesive-random-contact-fig3.png")] if several_adhesions else []
if len({row["p_bar/sqrtV"] for row in rows}) > 1 or not drawn:
    drawn.append((figure_4(), "adhesive-random-contact-fig4.png"))
for figure, name in drawn:
    corner_note(figure, folder)
    figure.tight_layout(rect=(0, 0.02, 1, 1))
    figure.savefig(folder / name, dpi=150)
    print(folder / name)
