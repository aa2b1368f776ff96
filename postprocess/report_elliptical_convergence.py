#!/usr/bin/python3
"""The convergence table of postprocess/benchmark_elliptical_convergence.sh:
for every elliptical-gap run in FOLDER (a folder with summary.csv and
parameters.prm), the largest relative K_I error over the front points on each
ring (against Green-Sneddon/Irwin under uniform pressure, Galin's closed form
under a quadratic traction), the errors of w(0) and of the gap volume,
DoFs, CG iterations, wall time and peak memory over both ranks.

Usage: /usr/bin/python3 postprocess/report_elliptical_convergence.py FOLDER
prints a Markdown table and writes it to FOLDER/convergence.md"""
import pathlib
import sys

from results import parameter, read_table

if len(sys.argv) != 2:
    sys.exit("usage: /usr/bin/python3 postprocess/report_elliptical_convergence.py FOLDER")
folder = pathlib.Path(sys.argv[1])


def traction(run):
    """The face traction of a run, as its table names it."""
    terms = [float(parameter(run, f"Traction {x}^2 term c_{x}", "0")) for x in "xy"]
    if terms == [0, 0]:
        return "uniform"
    return "p (1 " + " ".join(f"{'-' if c < 0 else '+'} {abs(c):g} {x}^2/{axis}^2"
                              for c, x, axis in zip(terms, "xy", "ab")) + ")"


runs = []
for run in (summary_file.parent for summary_file in folder.glob("*/summary.csv")):
    summary = {row["quantity"]: row["value"] for row in read_table(run, "summary.csv")}
    rings = [value for key, value in summary.items() if key.startswith("largest K_I relative error")]
    # Uniform pressure first, then by traction, b/a falling, refinements, degree.
    load = traction(run)
    discretisation = (load != "uniform", load, -float(parameter(run, "Aspect ratio b/a")),
                      int(parameter(run, "Global refinements")), int(parameter(run, "Polynomial degree")))
    runs.append((discretisation, summary, rings))
if not runs:
    sys.exit(f"report_elliptical_convergence.py: no runs in {folder}")

lines = ["| traction | b/a | degree | global refinements | DoFs | solver | largest K_I error, rings 0.1 / 0.2 / 0.4 b^2/a "
         "| w(0) error | gap volume error | wall time (s) | peak memory, both ranks (GB) |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
for (_, load, minus_aspect, refinements, degree), summary, rings in sorted(runs, key=lambda run: run[0]):
    solver = summary["solver"]
    if solver.startswith("CG"):
        solver += f", {summary['CG iterations']:.0f} its"
    lines.append(f"| {load} | {-minus_aspect:g} | {degree} | {refinements} | {summary['DoFs']:.0f} | {solver} | "
                 + " / ".join(f"{error:.1e}" for error in rings)
                 + f" | {summary['w(0) relative error']:.1e}"
                 + f" | {summary['gap volume relative error']:.1e}"
                 + f" | {summary['wall time total (s)']:.0f}"
                 + f" | {summary['peak memory, all ranks (MB)'] / 1024:.1f} |")
text = "\n".join(lines) + "\n"
(folder / "convergence.md").write_text(text)
print(text, end="")
