#!/usr/bin/python3
"""A measured surface: left, its isotropic PSD C(q) on log axes with the
power law fitted over the reliable range (shaded); right, the non-contact
area against the mean pressure of the map taken as one period and as an
isolated patch (the period alone on a refined grid). Reads
measured-surface.csv, measured-surface-psd.csv and measured-surface-contact.csv.

Usage: /usr/bin/python3 postprocess/plot_measured_surface.py OUTPUT_DIR
writes OUTPUT_DIR/measured-surface.png"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from results import corner_note, read_table  # noqa: E402

folder = pathlib.Path(sys.argv[1])
summary = {row["quantity"]: row["value"] for row in read_table(folder, "measured-surface.csv")}
psd = read_table(folder, "measured-surface-psd.csv")
contact = read_table(folder, "measured-surface-contact.csv")

figure, (spectrum, areas) = plt.subplots(1, 2, figsize=(12, 4.8))
spectrum.loglog([row["q (1/m)"] for row in psd], [row["C (m^4)"] for row in psd], "ko", ms=4,
                label="measured C(q), binned")
fitted = [row for row in psd if row["fitted"] == "yes"]
if fitted:
    spectrum.loglog([row["q (1/m)"] for row in fitted], [row["power-law fit (m^4)"] for row in fitted], "r-",
                    label=f"power law fitted, H = {summary['PSD fit: H']:.3f}, "
                          f"R^2 = {summary['PSD fit: R^2 of log C']:.3f}")
    spectrum.axvspan(summary["PSD fit: q_low (1/m)"], summary["PSD fit: q_high (1/m)"], color="tab:red",
                     alpha=0.08, label="reliable range: half the side to four pixels")
spectrum.set_xlabel("wavenumber q (1/m)")
spectrum.set_ylabel(r"isotropic PSD $C(q)$ (m$^4$)")
spectrum.set_title(f"the measured spectrum (rms height {summary['rms height (m)']:.3g} m, "
                   f"rms slope {summary['rms slope']:.3g})", fontsize=9)
spectrum.grid(alpha=0.3, which="both")
spectrum.legend(fontsize=7)
loads = [row["p_bar/sqrtV"] for row in contact]
areas.semilogy(loads, [row["A_nc/A_0 periodic"] for row in contact], "bo-", ms=4,
               label="the map as one period (periodic BEM)")
if "A_nc/A_0 patch" in contact[0]:  # not with Refinement > 1
    areas.semilogy(loads, [row["A_nc/A_0 patch"] for row in contact], "gs-", ms=4,
                   label="the map as an isolated patch (DC-FFT BEM)")
areas.set_xlabel(r"mean pressure $\bar p/\sqrt{V}$ (dimensionless)")
areas.set_ylabel(r"non-contact area $A_{nc}/A_0$ (dimensionless)")
areas.set_title("adhesionless contact: periodic or isolated", fontsize=9)
areas.grid(alpha=0.3, which="both")
areas.legend(fontsize=7)
corner_note(figure, folder)
figure.tight_layout(rect=(0, 0.02, 1, 1))
figure.savefig(folder / "measured-surface.png", dpi=120)
