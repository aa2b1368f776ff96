#!/usr/bin/python3
"""The bias of the front-localised domain integral that no mesh removes: the
3D elliptical model measures, at the front point phi_i, the average of the
energy release rate G(phi) ~ K_I(phi)^2 with the weight k((phi - phi_i)/h)
|dx/dphi| (src/fracture/front_segment_extension.h), and reports the square
root of that average as K_I(phi_i). Where K_I varies fast along the front (near
phi = 0 of a slender ellipse) the average differs from the point value even
for the exact field. This prints that relative difference for the exact
Green-Sneddon/Irwin K_I, for the weight in use, k(t) = (1 - t^2)^4 (1 - 10
t^2 + 17 t^4) (second and fourth moments zero), and for the earlier (1 -
t^2)^4 (1 - 13 t^2/3) (second moment zero), at the scene's 17 front points,
for the half-widths h = 2 and 1 front cells of 16 (h = 2 pi/32 and pi/32).

Usage: /usr/bin/python3 postprocess/front_weight_bias.py"""
import numpy as np

WEIGHTS = {
    "(1-t^2)^4 (1-10t^2+17t^4)": lambda t: (1 - t**2) ** 4 * (1 - 10 * t**2 + 17 * t**4),
    "(1-t^2)^4 (1-13t^2/3)": lambda t: (1 - t**2) ** 4 * (1 - 13 * t**2 / 3),
}


def bias(weight, aspect, h, centre):
    """sqrt(weighted average of G / G(centre)) - 1 for the ellipse a = 1, b = aspect.
    A weight reaching past phi = 0 or pi/2 is folded back, which for the even
    G and speed equals the unfolded average."""
    phi = np.linspace(centre - h, centre + h, 200001)
    energy = np.sqrt(np.sin(phi) ** 2 + aspect**2 * np.cos(phi) ** 2)  # G ~ K_I^2, up to a constant
    speed = np.sqrt(np.sin(phi) ** 2 + aspect**2 * np.cos(phi) ** 2)  # |dx/dphi|
    w = weight((phi - centre) / h) * speed
    average = np.trapz(w * energy, phi) / np.trapz(w, phi)
    exact = np.sqrt(np.sin(centre) ** 2 + aspect**2 * np.cos(centre) ** 2)
    return np.sqrt(average / exact) - 1


points = np.linspace(0, np.pi / 2, 17)
print("| weight | half-width (front cells of 16) | b/a | largest bias | at phi = 0 |")
print("|---|---|---|---|---|")
for name, weight in WEIGHTS.items():
    for cells in (2, 1):
        for aspect in (1, 0.5, 0.25, 0.1):
            biases = [bias(weight, aspect, cells * np.pi / 32, centre) for centre in points]
            print(f"| {name} | {cells} | {aspect:g} | {max(abs(b) for b in biases):.1e} | {biases[0]:+.1e} |")
