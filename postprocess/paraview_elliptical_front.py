"""The picture of an elliptical-gap result folder, drawn by ParaView:

  picture-front.png   the crack plane z = 0 of the quarter model seen from
                      above, coloured by the opening u_z, with the front as a
                      tube coloured by the FE K_I(phi) of the outermost ring
                      relative to the closed form (front.vtu); the title gives
                      the largest relative error over the front points.

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_elliptical_front.py RESULT_FOLDER [PNG_FOLDER]"""
import pathlib
import sys

import numpy
import paraview.simple as pv
from paraview import servermanager
from vtk.numpy_interface import dataset_adapter as dsa

folder = pathlib.Path(sys.argv[1])
pictures = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else folder
pictures.mkdir(parents=True, exist_ok=True)
size = [900, 700]

fields = pv.XMLUnstructuredGridReader(FileName=[str(folder / "solution.vtu")])
front = pv.XMLUnstructuredGridReader(FileName=[str(folder / "front.vtu")])
front.UpdatePipeline()

# K_I FE/exact - 1 at the front points, from the outermost ring (the last array).
data = dsa.WrapDataObject(servermanager.Fetch(front))
names = [name for name in data.PointData.keys() if name.startswith("K_I FE ring")]
if not names:
    sys.exit(f"{folder / 'front.vtu'} holds no K_I FE ring array")
ring = names[-1]
exact = numpy.asarray(data.PointData["K_I exact"])
relative = numpy.asarray(data.PointData[ring]) / exact - 1
points = numpy.asarray(data.Points)
semi_axis_a = points[:, 0].max()
with_error = pv.Calculator(Input=front, ResultArrayName="K_I FE/exact - 1")
with_error.Function = f'"{ring}"/"K_I exact" - 1'

view = pv.CreateView("RenderView")
view.ViewSize = size
view.OrientationAxesVisibility = 0
view.CameraParallelProjection = 1
view.Background = [1, 1, 1]
view.UseColorPaletteForBackground = 0

# The crack plane: the body sliced just above z = 0 (a slice in the boundary
# plane itself is empty), within 1.3 a of the centre.
plane = pv.Slice(Input=fields, SliceType="Plane")
plane.SliceType.Origin = [0, 0, 1e-6 * semi_axis_a]  # just inside the body
plane.SliceType.Normal = [0, 0, 1]
near = pv.Clip(Input=plane, ClipType="Box", Invert=1, Exact=1)
near.ClipType.Position = [0, 0, -1]
near.ClipType.Length = [1.3 * semi_axis_a, 1.3 * semi_axis_a, 2]
near.UpdatePipeline()
if near.GetDataInformation().GetNumberOfCells() == 0:
    sys.exit(f"{folder / 'solution.vtu'}: no cells in the crack plane z = 0 near the front")
near_display = pv.Show(near, view)
near_display.SetRepresentationType("Surface With Edges")
near_display.EdgeColor = [0.6, 0.6, 0.6]
pv.ColorBy(near_display, ("POINTS", "u", "Z"))
opening = pv.GetColorTransferFunction("u")
opening.VectorMode = "Component"
opening.VectorComponent = 2
opening.ApplyPreset("Grayscale", True)
opening.RescaleTransferFunction(*near.PointData["u"].GetRange(2))
opening_bar = pv.GetScalarBar(opening, view)
opening_bar.Title, opening_bar.ComponentTitle = "u_z (m)", ""
opening_bar.TitleColor = opening_bar.LabelColor = [0, 0, 0]
opening_bar.WindowLocation = "Any Location"
opening_bar.Position = [0.05, 0.1]
near_display.SetScalarBarVisibility(view, True)

tube = pv.Tube(Input=pv.ExtractSurface(Input=with_error))
tube.Radius = 0.012 * semi_axis_a
tube_display = pv.Show(tube, view)
pv.ColorBy(tube_display, ("POINTS", "K_I FE/exact - 1"))
error_colours = pv.GetColorTransferFunction("K_I FE/exact - 1")
error_colours.ApplyPreset("Cool to Warm", True)
largest = max(abs(relative).max(), 1e-300)
error_colours.RescaleTransferFunction(-largest, largest)
error_bar = pv.GetScalarBar(error_colours, view)
error_bar.Title, error_bar.ComponentTitle = "K_I FE/exact - 1", ""
error_bar.TitleColor = error_bar.LabelColor = [0, 0, 0]
error_bar.WindowLocation = "Any Location"
error_bar.Position = [0.87, 0.1]
tube_display.SetScalarBarVisibility(view, True)

title = pv.Text(Text=f"crack plane (opening u_z) and front, K_I against Green-Sneddon ({ring}): "
                     f"largest |error| {abs(relative).max():.2e} over {len(relative)} front points")
title_display = pv.Show(title, view)
title_display.Color = [0, 0, 0]
title_display.WindowLocation = "Upper Center"
title_display.FontSize = 12

centre = [0.65 * semi_axis_a, 0.65 * semi_axis_a, 0]
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0], centre[1], 10 * semi_axis_a]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 0.8 * semi_axis_a
pv.Render(view)
pv.SaveScreenshot(str(pictures / "picture-front.png"), view, ImageResolution=size)
print(pictures / "picture-front.png")
