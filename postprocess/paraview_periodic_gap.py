"""The picture of a periodic-gap result folder (Johnson's sinusoid as a
periodic array of gaps), drawn by ParaView from solution.vtu:

  picture-periodic-gap.png   the model near the face (a window as high as the
                             model is wide) with its mesh, the displacement
                             magnified so that the gap opens visibly,
                             coloured by u_y (the opening of the face)

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_periodic_gap.py RESULT_FOLDER [PNG_FOLDER]"""
import pathlib
import sys

import numpy
import paraview.simple as pv
from paraview import servermanager
from vtk.numpy_interface import dataset_adapter as dsa

folder = pathlib.Path(sys.argv[1])
pictures = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else folder
pictures.mkdir(parents=True, exist_ok=True)
size = [1000, 700]

fields = pv.XMLUnstructuredGridReader(FileName=[str(folder / "solution.vtu")])
fields.UpdatePipeline()
data = dsa.WrapDataObject(servermanager.Fetch(fields))
if "u" not in data.PointData.keys():
    sys.exit(f"{folder / 'solution.vtu'} holds no displacement u")
x0, x1, y0, y1 = data.GetBounds()[:4]
largest = numpy.abs(numpy.asarray(data.PointData["u"])).max()
magnification = 0.1 * (x1 - x0) / largest if largest > 0 else 1

warped = pv.WarpByVector(Input=fields, Vectors=["POINTS", "u"], ScaleFactor=magnification)
view = pv.CreateView("RenderView")
view.ViewSize = size
view.OrientationAxesVisibility = 0
view.CameraParallelProjection = 1
view.Background = [1, 1, 1]
view.UseColorPaletteForBackground = 0
display = pv.Show(warped, view)
display.SetRepresentationType("Surface With Edges")
display.EdgeColor = [0.2, 0.2, 0.2]
pv.ColorBy(display, ("POINTS", "u", "Y"))
colours = pv.GetColorTransferFunction("u")
colours.VectorMode = "Component"
colours.VectorComponent = 1
colours.RescaleTransferFunction(*fields.PointData["u"].GetRange(1))
bar = pv.GetScalarBar(colours, view)
bar.Title, bar.ComponentTitle = "u_y (m)", ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.WindowLocation = "Any Location"
bar.Position = [0.89, 0.1]
display.SetScalarBarVisibility(view, True)
title = pv.Text(Text=f"periodic gap with its mesh, displacement magnified {magnification:.3g} times")
title_display = pv.Show(title, view)
title_display.Color = [0, 0, 0]
title_display.WindowLocation = "Upper Center"
title_display.FontSize = 13

# The window of one width above the face, where the gap and the graded mesh
# are (after a first render, which resets the camera).
pv.Render(view)
width = x1 - x0
centre = [(x0 + x1) / 2, y0 + 0.5 * width, 0]
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0], centre[1], 10 * width]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 0.6 * width
pv.Render(view)
pv.SaveScreenshot(str(pictures / "picture-periodic-gap.png"), view, ImageResolution=size)
print(pictures / "picture-periodic-gap.png")
