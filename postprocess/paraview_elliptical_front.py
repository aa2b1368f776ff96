"""The picture of an elliptical-gap result folder, drawn by ParaView:

  picture-front.png   the crack plane z = 0 of the quarter model seen from
                      above, coloured by the opening u_z, with the front as a
                      tube coloured by the FE K_I(phi) of the outermost ring
                      relative to the closed form (front.vtu); the title gives
                      the largest relative error over the front points.

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_elliptical_front.py RESULT_FOLDER [PNG_FOLDER]"""
import sys

import numpy
import paraview.simple as pv

from paraview_common import (colour_bar, fetched, folders, look_at, mesh_coloured_by_component, save,
                             symmetric_colours, title, white_view)

folder, pictures = folders()
size = [900, 700]

fields = pv.XMLUnstructuredGridReader(FileName=[str(folder / "solution.vtu")])
front = pv.XMLUnstructuredGridReader(FileName=[str(folder / "front.vtu")])

# K_I FE/exact - 1 at the front points, from the outermost ring (the last array).
data = fetched(front)
names = [name for name in data.PointData.keys() if name.startswith("K_I FE ring")]
if not names:
    sys.exit(f"{folder / 'front.vtu'} holds no K_I FE ring array")
ring = names[-1]
relative = numpy.asarray(data.PointData[ring]) / numpy.asarray(data.PointData["K_I exact"]) - 1
semi_axis_a = numpy.asarray(data.Points)[:, 0].max()
with_error = pv.Calculator(Input=front, ResultArrayName="K_I FE/exact - 1")
with_error.Function = f'"{ring}"/"K_I exact" - 1'

view = white_view(size)
# The crack plane: the body sliced just above z = 0 (a slice in the boundary
# plane itself is empty), within 1.3 a of the centre.
plane = pv.Slice(Input=fields, SliceType="Plane")
plane.SliceType.Origin = [0, 0, 1e-6 * semi_axis_a]
plane.SliceType.Normal = [0, 0, 1]
near = pv.Clip(Input=plane, ClipType="Box", Invert=1, Exact=1)
near.ClipType.Position = [0, 0, -1]
near.ClipType.Length = [1.3 * semi_axis_a, 1.3 * semi_axis_a, 2]
near.UpdatePipeline()
if near.GetDataInformation().GetNumberOfCells() == 0:
    sys.exit(f"{folder / 'solution.vtu'}: no cells in the crack plane z = 0 near the front")
opening = mesh_coloured_by_component(view, near, 2, 0.6, "u_z (m)", [0.05, 0.1])
opening.ApplyPreset("Grayscale", False)

tube = pv.Tube(Input=pv.ExtractSurface(Input=with_error))
tube.Radius = 0.012 * semi_axis_a
tube_display = pv.Show(tube, view)
pv.ColorBy(tube_display, ("POINTS", "K_I FE/exact - 1"))
error_colours = symmetric_colours("K_I FE/exact - 1", max(abs(relative).max(), 1e-300))
colour_bar(view, tube_display, error_colours, "K_I FE/exact - 1", [0.87, 0.1])
title(view, f"crack plane (opening u_z) and front, K_I against Green-Sneddon ({ring}): "
            f"largest |error| {abs(relative).max():.2e} over {len(relative)} front points", 12)

look_at(view, [0.65 * semi_axis_a, 0.65 * semi_axis_a, 0], 0.8 * semi_axis_a, 10 * semi_axis_a)
save(view, pictures / "picture-front.png", size)
