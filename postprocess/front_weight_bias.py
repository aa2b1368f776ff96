#!/usr/bin/python3
"""The bias of the front-localised domain integral that no mesh removes: the
3D elliptical model measures, at the front point phi_i, the average of the
energy release rate G(phi) ~ K_I(phi)^2 with the weight k((psi - psi_i)/h)
|dx/dphi| dphi (src/fracture/front_segment_extension.h), psi the front
coordinate (phi + alpha)/2 (alpha the normal's angle; the mesh's columns are
evenly spaced in it), and reports the square root of that average as
K_I(phi_i). Where K_I varies fast along the front (near phi = 0 of a slender
ellipse) the average differs from the point value even for the exact field.
This prints that relative difference for the exact Green-Sneddon/Irwin K_I,
for the two weights of `Elliptical model/Front weight moments`: 5 (the
default), k(t) = (1 - t^2)^4 (1 - 10 t^2 + 17 t^4), and 7, (1 - t^2)^4 (1 -
17 t^2 + (323/5) t^4 - (323/5) t^6), whose moments of orders 1 to 5 and 1 to
7 vanish, at the scene's 17 front points (evenly spaced in psi), for the
half-widths h = 2 and 1 front cells of 16 (h = 2 pi/32 and pi/32), with the
weight in the front coordinate psi (in use) and, for the default, in the
parametric angle phi (before the mesh's columns were spaced in psi).

Usage: /usr/bin/python3 postprocess/front_weight_bias.py"""
import numpy as np


def weight_moments_7(t):
    return np.where(np.abs(t) < 1, (1 - t**2) ** 4 * (1 - 17 * t**2 + 64.6 * t**4 - 64.6 * t**6), 0)


def weight_moments_5(t):
    return np.where(np.abs(t) < 1, (1 - t**2) ** 4 * (1 - 10 * t**2 + 17 * t**4), 0)


def coordinate(phi, aspect, spacing):
    """psi(phi) on -pi/2 < phi < pi (continuous there), or phi itself."""
    if spacing == "phi":
        return phi
    return (phi + np.arctan2(np.sin(phi), aspect * np.cos(phi))) / 2


# The integration grid, past both symmetry planes: the unfolded average over
# the whole front equals the folded one over the quarter, G and the speed
# being even about phi = 0 and pi/2.
PHI = np.linspace(-np.pi / 2 + 1e-9, np.pi - 1e-9, 2000001)


def bias(weight, aspect, h, centre, spacing):
    """sqrt(weighted average of G / G(centre)) - 1 for the ellipse a = 1, b = aspect."""
    speed = np.sqrt(np.sin(PHI) ** 2 + aspect**2 * np.cos(PHI) ** 2)  # |dx/dphi|
    energy = speed  # G ~ K_I^2 ~ (sin^2 + (b/a)^2 cos^2)^(1/2), up to a constant
    w = weight((coordinate(PHI, aspect, spacing) - coordinate(centre, aspect, spacing)) / h) * speed
    average = np.trapz(w * energy, PHI) / np.trapz(w, PHI)
    exact = np.sqrt(np.sin(centre) ** 2 + aspect**2 * np.cos(centre) ** 2)
    return np.sqrt(average / exact) - 1


def parametric_angle(psi, aspect):
    """phi of front coordinate psi, by bisection (psi rises with phi on [0, pi/2])."""
    lo, hi = 0.0, np.pi / 2
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if coordinate(mid, aspect, "psi") < psi else (lo, mid)
    return (lo + hi) / 2


print("| moments zero | in | half-width (front cells of 16) | b/a | largest bias | at phi |")
print("|---|---|---|---|---|---|")
WEIGHTS = (("1 to 5", weight_moments_5, ("psi", "phi")), ("1 to 7", weight_moments_7, ("psi",)))
for name, weight, spacings in WEIGHTS:
    for spacing in spacings:
        for cells in (2, 1):
            for aspect in (1, 0.5, 0.25, 0.1, 0.05):
                points = [parametric_angle(psi, aspect) for psi in np.linspace(0, np.pi / 2, 17)]
                biases = [bias(weight, aspect, cells * np.pi / 32, centre, spacing) for centre in points]
                worst = int(np.argmax(np.abs(biases)))
                row = f"| {name} | {spacing} | {cells} | {aspect:g} | {biases[worst]:+.1e} | {points[worst]:.2f} |"
                print(row)
