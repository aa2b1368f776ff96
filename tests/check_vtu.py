"""Runs a penny scene that writes fields and reads both VTU files back with
VTK's reader: the named arrays with their components, the gap opening, the
tip frame (coordinates (r - c)/c, z/c, the tip at the origin) with every cell
of positive area down to the finest (the Float32 coordinates must not collapse
the graded cells), and the opening profile; then runs it with
'Write fields = false' and checks that no VTU is written.
Usage: check_vtu.py PENNY SCENE.prm"""
import csv
import pathlib
import subprocess
import sys
import tempfile

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy

penny, scene = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
expected = {"u": 3, "u_r": 1, "u_z": 1, "sigma_rr": 1, "sigma_zz": 1, "sigma_hoop": 1, "sigma_rz": 1,
            "von_mises": 1, "q_weight": 1}


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() > 0, f"{path.name}: no cells"
    data = grid.GetPointData()
    for name, components in expected.items():
        array = data.GetArray(name)
        assert array is not None, f"{path.name}: array {name} missing"
        assert array.GetNumberOfComponents() == components, f"{name}: {array.GetNumberOfComponents()} components"
        assert numpy.isfinite(vtk_to_numpy(array)).all(), f"{path.name}: {name} holds NaN or Inf"
    return grid


def corner_areas(grid):
    """Areas of the cells' corner quadrilaterals (a Lagrange cell lists its corners first)."""
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    areas = []
    for i in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(i).GetPointIds()
        x, y = points[[ids.GetId(k) for k in range(4)], 0], points[[ids.GetId(k) for k in range(4)], 1]
        areas.append(0.5 * abs(numpy.dot(x, numpy.roll(y, -1)) - numpy.dot(y, numpy.roll(x, -1))))
    return numpy.array(areas)


with tempfile.TemporaryDirectory() as work:
    work = pathlib.Path(work)
    subprocess.run([penny, str(scene)], cwd=work, check=True, stdout=subprocess.DEVNULL)
    out = work / "fields"
    for name in ("solution", "solution-tip"):
        assert f'file="{name}.vtu"' in (out / f"{name}.pvd").read_text(), f"{name}.pvd does not list {name}.vtu"

    whole = read(out / "solution.vtu")
    data = whole.GetPointData()
    q = vtk_to_numpy(data.GetArray("q_weight"))
    assert abs(q.max() - 1) < 1e-12 and q.min() == 0, "q_weight is not 1 at the tip and 0 far away"
    assert vtk_to_numpy(data.GetArray("u_z")).max() > 0, "the gap does not open"

    tip = read(out / "solution-tip.vtu")
    points = vtk_to_numpy(tip.GetPoints().GetData())
    assert numpy.hypot(points[:, 0], points[:, 1]).min() == 0, "the tip is not at the origin of the tip frame"
    assert points[:, 0].min() >= -1.5 and points[:, 0].max() <= 1.5 and points[:, 1].max() <= 1.5
    areas = corner_areas(tip)
    sizes = numpy.sort(areas)
    assert sizes[0] > 0, f"{(areas == 0).sum()} cells of zero area in the tip frame"
    print(f"tip frame: {len(areas)} cells, the smallest {numpy.sqrt(sizes[0]):.2e} c wide, none collapsed")

    with open(out / "opening.csv") as table:
        rows = list(csv.DictReader(table))
    assert len(rows) > 10 and float(rows[0]["r/c"]) == 0, "opening.csv does not start at the centre"
    worst = max(abs(float(row["w FE (m)"]) - float(row["w exact (m)"])) for row in rows) / float(rows[0]["w exact (m)"])
    assert worst < 1e-2, f"the opening profile is {worst:.1e} off"

    no_fields = work / "no-fields.prm"
    no_fields.write_text(scene.read_text().replace("set Write fields = true", "set Write fields = false"))
    subprocess.run([penny, str(no_fields)], cwd=work, check=True, stdout=subprocess.DEVNULL)
    assert not (out / "solution.vtu").exists(), "a scene with 'Write fields = false' wrote a VTU"
print("VTU arrays found:", ", ".join(expected))
