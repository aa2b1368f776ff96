"""Runs the penny-gap scene at test size under non-smooth and smooth
expression loads (a step, a kink, a square-root edge at the tip and inside
the gap, a Gaussian) and checks that each run ends, with K_I, w(0) and the gap
volume beside closed forms whose quadrature error estimate is printed and
small, and with the FE within the stated tolerances of them. The rings stay
clear of the load's jumps and kinks (J's face term is exact only where the
load is smooth inside the ring). Usage: check_expression_loads.py PENNY"""
import csv
import pathlib
import subprocess
import sys
import tempfile

penny = sys.argv[1]
# Expression, largest relative K_I, w(0) and volume differences FE vs closed
# form at this test size (degree 3, 20 tip levels): the FE resolves a jump or
# a square-root edge inside the gap only to these.
loads = [
    ("P * (r < c/2)", 1e-4, 1e-3, 1e-5),
    ("P * abs(r/c - 0.5)", 1e-5, 1e-3, 1e-5),
    ("P * sqrt(1 - (r/c)^2)", 1e-5, 1e-5, 1e-5),
    ("P * sqrt(max(0, 1 - 4 * (r/c)^2))", 3e-3, 1e-3, 3e-3),
    ("P * exp(-(r/c)^2)", 1e-5, 1e-4, 1e-5),
]
scene = """set Scene = penny-gap
subsection Load
  set Type = expression
  set Expression = {expression}
end
subsection Mesh
  set Tip refinement levels = 20
end
subsection Finite element
  set Polynomial degree = 3
end
subsection J-integral
  set Ring radii = 0.2, 0.4
end
subsection Fields
  set Write fields = false
end
subsection Verification
  # The scene's own verdict is loose here: this script checks each quantity.
  set Tolerance = 1e-2
end
subsection Output
  set Directory = out
end
"""
failures = []
with tempfile.TemporaryDirectory() as work:
    for expression, k_tolerance, w_tolerance, v_tolerance in loads:
        prm = pathlib.Path(work) / "load.prm"
        prm.write_text(scene.format(expression=expression))
        run = subprocess.run([penny, str(prm)], cwd=work, capture_output=True, text=True, timeout=120)
        if run.returncode != 0:
            failures.append(f"{expression}: exit status {run.returncode}: {run.stderr.strip()}")
            continue
        out = pathlib.Path(work) / "out"
        summary = {row["quantity"]: row["value"] for row in csv.DictReader(open(out / "summary.csv"))}
        rings = list(csv.DictReader(open(out / "rings.csv")))
        k_error = max(float(row["|K_I| relative error"]) for row in rings)
        checks = [
            ("K_I", k_error, k_tolerance),
            ("w(0)", float(summary["opening relative error"]), w_tolerance),
            ("volume", float(summary["volume relative error"]), v_tolerance),
        ]
        estimates = {name: float(summary[f"{name} exact: quadrature error estimate (relative)"])
                     for name in ("K_I", "w(0)", "gap volume")}
        print(f"{expression:36s} K_I {k_error:.1e}  w(0) {checks[1][1]:.1e}  volume {checks[2][1]:.1e}  "
              f"quadrature error estimates {', '.join(f'{v:.1e}' for v in estimates.values())}  "
              f"closed form {float(summary['wall time closed form (s)']):.1e} s")
        for name, error, tolerance in checks:
            if not error <= tolerance:
                failures.append(f"{expression}: {name} differs by {error:.2e} > {tolerance:.0e}")
        for name, estimate in estimates.items():
            if not estimate <= 1e-10:
                failures.append(f"{expression}: {name} quadrature error estimate {estimate:.2e} > 1e-10")
        if "quadrature" not in summary["closed forms"]:
            failures.append(f"{expression}: the summary does not say the closed forms are quadratures")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
