"""Runs a short convergence sequence, checks that the K_I error falls from
cycle to cycle with a positive observed rate, and that the plotting script
draws both figures.  Usage: check_convergence.py PENNY SCENE.prm PLOT_SCRIPT"""
import csv
import pathlib
import subprocess
import sys
import tempfile

penny, scene, plot = sys.argv[1], pathlib.Path(sys.argv[2]).resolve(), sys.argv[3]
with tempfile.TemporaryDirectory() as work:
    work = pathlib.Path(work)
    subprocess.run([penny, str(scene)], cwd=work, check=True, stdout=subprocess.DEVNULL)
    with open(work / "convergence" / "convergence.csv") as table:
        rows = list(csv.DictReader(table))
    errors = [float(row["relative error"]) for row in rows]
    assert len(errors) == 3, f"{len(errors)} cycles"
    assert all(later < earlier for earlier, later in zip(errors, errors[1:])), f"errors do not fall: {errors}"
    assert all(float(row["rate"]) > 0 for row in rows[1:]), "non-positive rate"
    assert all(float(row["peak memory (MiB)"]) > 0 and float(row["wall (s)"]) > 0 for row in rows)
    subprocess.run(["/usr/bin/python3", plot, str(work / "conv"), str(work / "convergence")],
                   check=True, stdout=subprocess.DEVNULL)
    for suffix in ("dofs", "time"):
        assert (work / f"conv-{suffix}.png").stat().st_size > 0
print("errors fall:", ", ".join(f"{e:.3e}" for e in errors))
