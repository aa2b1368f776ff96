"""Runs a penny scene that writes fields, reads the VTU back with VTK's reader
and checks the named arrays; then runs it with 'Write fields = false' and checks
that no VTU is written.  Usage: check_vtu.py PENNY SCENE.prm"""
import pathlib
import subprocess
import sys
import tempfile

import vtk
from vtk.util.numpy_support import vtk_to_numpy

penny, scene = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
expected = {"displacement": 3, "sigma_rr": 1, "sigma_zz": 1, "sigma_tt": 1,
            "sigma_rz": 1, "von_mises": 1, "q_weight": 1}

with tempfile.TemporaryDirectory() as work:
    work = pathlib.Path(work)
    subprocess.run([penny, str(scene)], cwd=work, check=True, stdout=subprocess.DEVNULL)
    out = work / "fields"
    assert 'file="solution.vtu"' in (out / "solution.pvd").read_text(), "PVD does not list solution.vtu"

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(out / "solution.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfPoints() > 0, "empty grid"
    data = grid.GetPointData()
    for name, components in expected.items():
        array = data.GetArray(name)
        assert array is not None, f"array {name} missing"
        assert array.GetNumberOfComponents() == components, f"{name}: {array.GetNumberOfComponents()} components"
        values = vtk_to_numpy(array)
        assert (values == values).all(), f"{name} holds NaN"
    q = vtk_to_numpy(data.GetArray("q_weight"))
    assert abs(q.max() - 1) < 1e-12 and q.min() == 0, "q_weight is not 1 at the tip and 0 far away"
    uz = vtk_to_numpy(data.GetArray("displacement"))[:, 1]
    assert uz.max() > 0, "the gap does not open"

    (out / "solution.vtu").unlink()
    no_fields = work / "no-fields.prm"
    no_fields.write_text(scene.read_text().replace("set Write fields = true", "set Write fields = false"))
    subprocess.run([penny, str(no_fields)], cwd=work, check=True, stdout=subprocess.DEVNULL)
    assert not (out / "solution.vtu").exists(), "a scene with 'Write fields = false' wrote a VTU"
print("VTU arrays found:", ", ".join(expected))
