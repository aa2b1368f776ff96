"""The picture of a periodic-gap result folder (Johnson's sinusoid as a
periodic array of gaps), drawn by ParaView from solution.vtu:

  picture-periodic-gap.png   the model near the face (a window as high as the
                             model is wide) with its mesh, the displacement
                             magnified so that the gap opens visibly,
                             coloured by u_y (the opening of the face)

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_periodic_gap.py RESULT_FOLDER [PNG_FOLDER]"""
import sys

import numpy
import paraview.simple as pv

from paraview_common import fetched, folders, look_at, mesh_coloured_by_component, save, title, white_view

folder, pictures = folders()
size = [1000, 700]

fields = pv.XMLUnstructuredGridReader(FileName=[str(folder / "solution.vtu")])
data = fetched(fields)
if "u" not in data.PointData.keys():
    sys.exit(f"{folder / 'solution.vtu'} holds no displacement u")
x0, x1, y0, y1 = data.GetBounds()[:4]
width = x1 - x0
largest = numpy.abs(numpy.asarray(data.PointData["u"])).max()
magnification = 0.1 * width / largest if largest > 0 else 1

view = white_view(size)
warped = pv.WarpByVector(Input=fields, Vectors=["POINTS", "u"], ScaleFactor=magnification)
mesh_coloured_by_component(view, warped, 1, 0.2, "u_y (m)", [0.89, 0.1])
title(view, f"periodic gap with its mesh, displacement magnified {magnification:.3g} times")

# The window of one width above the face, where the gap and the graded mesh are.
look_at(view, [(x0 + x1) / 2, y0 + 0.5 * width, 0], 0.6 * width, 10 * width)
save(view, pictures / "picture-periodic-gap.png", size)
