"""Wall time of the whole penny process to reach a K_I accuracy, for the
penny-gap scene (uniform pressure) and the periodic-gap scene of the sinusoid.

Each candidate discretisation (degree, tip levels, grading distance, domain
size, degree grading) runs as its own process, timed from start to exit (the best of
--repeat runs); the error is the largest relative K_I error over the rings
(|K_I| and signed). For each target the fastest candidate that reaches it is
reported. Usage:

  /usr/bin/python3 postprocess/benchmark_accuracy.py build/penny [--repeat N] [--out FOLDER]

writes FOLDER/accuracy-candidates.csv and FOLDER/accuracy-targets.csv
(default output/benchmark-accuracy) and prints both tables."""
import argparse
import csv
import os
import pathlib
import subprocess
import tempfile
import time

TARGETS = [1e-6, 1e-8, 1e-10]

# (degree, tip levels, grading distance, R/c = H/c, tip levels per degree step);
# R/c = 1e3 truncates at (c/R)^3 = 1e-9, so the candidates aiming below it use
# 1e5. The last entry grades the degree down towards the tip (0: uniform).
PENNY = [(2, 12, 2, 1e3, 0), (3, 16, 2, 1e3, 0), (4, 16, 2, 1e3, 0), (4, 20, 2, 1e3, 0),
         (4, 24, 1.5, 1e3, 8), (5, 28, 1.5, 1e3, 8), (5, 30, 2, 1e5, 8), (6, 30, 2, 1e5, 0),
         (6, 32, 1.5, 1e5, 8), (6, 36, 1.5, 1e5, 8), (6, 34, 2, 1e5, 8), (7, 36, 1.5, 1e5, 8),
         (8, 36, 2, 1e5, 0)]
# (degree, tip levels, grading distance, D/lambda, 0): the periodic model has one degree.
PERIODIC = [(2, 12, 2, 3, 0), (3, 16, 2, 3, 0), (4, 16, 3, 3, 0), (4, 20, 3, 3, 0), (4, 24, 3, 3, 0),
            (5, 24, 3, 3, 0), (6, 24, 3, 3, 0)]


def penny_scene(degree, levels, grading, size, levels_per_degree):
    return f"""set Scene = penny-gap
subsection Geometry
  set Domain radius R = {size:g}
  set Domain height H = {size:g}
end
subsection Mesh
  set Tip refinement levels = {levels}
  set Grading distance = {grading}
end
subsection Finite element
  set Polynomial degree = {degree}
  set Degree grading = {levels_per_degree}
end
subsection Fields
  set Write fields = false
end
subsection Verification
  set Tolerance = 1
end
subsection Output
  set Directory = out
end
"""


def periodic_scene(degree, levels, grading, depth, _):
    return f"""set Scene = periodic-gap
subsection Periodic gap
  set Depth D = {depth:g}
  set Tip refinement levels = {levels}
  set Grading distance = {grading}
end
subsection Finite element
  set Polynomial degree = {degree}
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


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("penny")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--out", default="output/benchmark-accuracy")
    args = parser.parse_args()
    penny = os.path.abspath(args.penny)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    candidates = []
    for model, scene, settings in (("penny-gap", penny_scene, PENNY), ("periodic-gap", periodic_scene, PERIODIC)):
        for setting in settings:
            seconds, error, dofs = run(penny, scene(*setting), args.repeat)
            candidates.append((model, *setting, dofs, error, seconds))
            print(f"{model:13s} degree {setting[0]} levels {setting[1]:2d} grading {setting[2]} "
                  f"size {setting[3]:g} degree grading {setting[4]}: {dofs:7d} DoFs  error {error:.2e}  "
                  f"{seconds:.2f} s", flush=True)

    header = ["model", "degree", "tip levels", "grading distance", "R/c or D/lambda", "degree grading", "DoFs",
              "largest K_I relative error", "process wall time (s)"]
    with open(out / "accuracy-candidates.csv", "w", newline="") as f:
        csv.writer(f).writerows([header] + candidates)

    rows = [["model", "target", "process wall time (s)", "degree", "tip levels", "grading distance",
             "R/c or D/lambda", "degree grading", "DoFs", "error reached"]]
    for model in ("penny-gap", "periodic-gap"):
        for target in TARGETS:
            reaching = [c for c in candidates if c[0] == model and c[7] <= target]
            if reaching:
                best = min(reaching, key=lambda c: c[8])
                rows.append([model, f"{target:.0e}", f"{best[8]:.2f}", *best[1:7], f"{best[7]:.1e}"])
            else:
                rows.append([model, f"{target:.0e}", "not reached", "", "", "", "", "", "", ""])
    with open(out / "accuracy-targets.csv", "w", newline="") as f:
        csv.writer(f).writerows(rows)
    print()
    for row in rows:
        print("  ".join(f"{str(cell):>16s}" for cell in row))
    print(f"\nload average at the end: {os.getloadavg()[0]:.1f} ({os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
