"""Wall time of the whole penny process to reach a K_I accuracy, for the
penny-gap scene (uniform pressure) and the periodic-gap scene of the sinusoid,
and the K_I error against DoFs and wall time for degrees 1 to 8.

Each discretisation (degree, tip levels, grading distance, domain size,
degree grading) runs as its own process, timed from start to exit (the best
of --repeat runs); the error is the largest relative error over the rings of
|K_I| and the signed K_I. Two sets of runs:
- a ladder of discretisations: for each target 1e-6, 1e-8, 1e-10 the fastest
  run that reaches it is reported;
- degrees 1 to 8 on one mesh per model (the mesh of ten digits), with one
  degree on every cell and with the degree graded towards the tip.
Usage:

  /usr/bin/python3 postprocess/benchmark_accuracy.py build/penny [--repeat N] [--out FOLDER]

writes FOLDER/accuracy-runs.csv, FOLDER/accuracy-targets.csv and
FOLDER/accuracy-degrees.png (error against DoFs and against wall time), default
output/benchmark-accuracy, and prints the tables."""
import argparse
import csv
import os
import pathlib
import subprocess
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TARGETS = [1e-6, 1e-8, 1e-10]
MODELS = ["penny-gap", "periodic-gap"]

# (degree, tip levels, grading distance, size, tip levels per degree step).
# Size: R/c = H/c for the penny gap, whose truncation costs (c/R)^3, so the
# runs aiming below 1e-9 use 1e5; D/lambda for the periodic gap, whose
# truncation falls like exp(-2 pi D/lambda). Degree grading 0: one degree.
LADDER = {
    "penny-gap": [(2, 12, 2, 1e3, 0), (3, 16, 2, 1e3, 0), (4, 16, 2, 1e3, 0), (4, 20, 2, 1e3, 0),
                  (4, 24, 1.5, 1e3, 8), (4, 24, 1.75, 1e3, 7), (5, 28, 1.5, 1e3, 8), (5, 30, 1.75, 1e4, 7),
                  (6, 30, 2, 1e5, 0), (6, 32, 1.5, 1e5, 8), (6, 32, 1.75, 1e4, 8), (6, 32, 1.75, 1e4, 7),
                  (6, 36, 1.5, 1e5, 8), (7, 36, 1.5, 1e5, 8), (8, 36, 2, 1e5, 0)],
    "periodic-gap": [(2, 12, 2, 3, 0), (3, 16, 2, 3, 0), (4, 16, 3, 3, 0), (4, 20, 3, 3, 0), (4, 24, 3, 3, 0),
                     (4, 20, 2, 3, 8), (5, 24, 2, 3, 8), (5, 28, 1.5, 3, 8), (6, 30, 1.5, 3, 8),
                     (6, 32, 1.5, 3, 8), (7, 32, 1.5, 3, 8)],
}
# The mesh of the degree sweeps: (tip levels, grading distance, size).
DEGREE_MESH = {"penny-gap": (32, 1.75, 1e4), "periodic-gap": (32, 1.5, 3)}
DEGREE_GRADINGS = [0, 8]


def scene(model, degree, levels, grading, size, degree_grading):
    if model == "penny-gap":
        domain = f"""subsection Geometry
  set Domain radius R = {size:g}
  set Domain height H = {size:g}
end
subsection Mesh
  set Tip refinement levels = {levels}
  set Grading distance = {grading}
end
subsection Fields
  set Write fields = false
end
"""
    else:
        domain = f"""subsection Periodic gap
  set Depth D = {size:g}
  set Tip refinement levels = {levels}
  set Grading distance = {grading}
end
"""
    return f"""set Scene = {model}
{domain}subsection Finite element
  set Polynomial degree = {degree}
  set Degree grading = {degree_grading}
end
subsection Verification
  set Tolerance = 1
end
subsection Output
  set Directory = out
end
"""


def run(penny, text, repeat):
    """Best whole-process wall time (s), largest ring error and DoFs."""
    with tempfile.TemporaryDirectory() as work:
        prm = pathlib.Path(work) / "scene.prm"
        prm.write_text(text)
        best = float("inf")
        for _ in range(repeat):
            start = time.perf_counter()
            done = subprocess.run([penny, str(prm)], cwd=work, capture_output=True, text=True)
            best = min(best, time.perf_counter() - start)
            if done.returncode != 0:
                raise SystemExit(f"penny failed on\n{text}\n{done.stderr}")
        rings = list(csv.DictReader(open(pathlib.Path(work) / "out" / "rings.csv")))
        summary = {r["quantity"]: r["value"] for r in csv.DictReader(open(pathlib.Path(work) / "out" / "summary.csv"))}
        error_columns = [c for c in rings[0] if "relative error" in c]
        error = max(float(row[c]) for row in rings for c in error_columns)
        return best, error, int(summary["DoFs"])


def plot(runs, path):
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for model, colour in zip(MODELS, ("tab:blue", "tab:red")):
        for degree_grading, style in zip(DEGREE_GRADINGS, ("o-", "s--")):
            sweep = sorted((r for r in runs if r["set"] == "degrees" and r["model"] == model
                            and r["degree grading"] == degree_grading), key=lambda r: r["degree"])
            label = f"{model}, " + ("one degree" if degree_grading == 0 else f"degree graded (1 per {degree_grading} levels)")
            for ax, x in zip(axes, ("DoFs", "process wall time (s)")):
                ax.loglog([r[x] for r in sweep], [r["error"] for r in sweep], style, color=colour, label=label)
                for r in sweep:
                    ax.annotate(str(r["degree"]), (r[x], r["error"]), fontsize=7, xytext=(3, 3),
                                textcoords="offset points")
    for ax, x in zip(axes, ("DoFs", "whole-process wall time (s)")):
        ax.set_xlabel(x)
        ax.set_ylabel("largest relative K_I error")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    figure.suptitle("K_I error for degrees 1 to 8 (numbers), tip-graded meshes of 32 levels "
                    f"(grading distance {DEGREE_MESH['penny-gap'][1]} and {DEGREE_MESH['periodic-gap'][1]})")
    figure.tight_layout()
    figure.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("penny", help="the penny executable (a Release build)")
    parser.add_argument("--repeat", type=int, default=3, help="runs per discretisation, the best counts (>= 1)")
    parser.add_argument("--out", default="output/benchmark-accuracy")
    args = parser.parse_args()
    penny = os.path.abspath(args.penny)
    if not (os.path.isfile(penny) and os.access(penny, os.X_OK)):
        parser.error(f"{args.penny} is not an executable file")
    if args.repeat < 1:
        parser.error(f"--repeat {args.repeat}: at least 1")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    settings = [("ladder", model, *setting) for model in MODELS for setting in LADDER[model]]
    settings += [("degrees", model, degree, *DEGREE_MESH[model], degree_grading)
                 for model in MODELS for degree_grading in DEGREE_GRADINGS for degree in range(1, 9)]
    keys = ["set", "model", "degree", "tip levels", "grading distance", "size", "degree grading"]
    runs = []
    for setting in settings:
        seconds, error, dofs = run(penny, scene(*setting[1:]), args.repeat)
        runs.append(dict(zip(keys, setting), DoFs=dofs, error=error, **{"process wall time (s)": seconds}))
        print(f"{setting[0]:8s}{setting[1]:13s} degree {setting[2]} levels {setting[3]:2d} grading {setting[4]} "
              f"size {setting[5]:g} degree grading {setting[6]}: {dofs:7d} DoFs  error {error:.2e}  {seconds:.2f} s",
              flush=True)
    with open(out / "accuracy-runs.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(runs[0]))
        writer.writeheader()
        writer.writerows(runs)

    rows = [["model", "target", "process wall time (s)", "degree", "tip levels", "grading distance",
             "R/c or D/lambda", "degree grading", "DoFs", "error reached"]]
    for model in MODELS:
        for target in TARGETS:
            reaching = [r for r in runs if r["model"] == model and r["error"] <= target]
            if reaching:
                best = min(reaching, key=lambda r: r["process wall time (s)"])
                rows.append([model, f"{target:.0e}", f"{best['process wall time (s)']:.2f}"]
                            + [best[k] for k in keys[2:]] + [best["DoFs"], f"{best['error']:.1e}"])
            else:
                rows.append([model, f"{target:.0e}", "not reached"] + [""] * 7)
    with open(out / "accuracy-targets.csv", "w", newline="") as f:
        csv.writer(f).writerows(rows)
    plot(runs, out / "accuracy-degrees.png")
    print()
    for row in rows:
        print("  ".join(f"{str(cell):>16s}" for cell in row))
    print(f"\n{out / 'accuracy-degrees.png'}; load average at the end: {os.getloadavg()[0]:.1f} ({os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
