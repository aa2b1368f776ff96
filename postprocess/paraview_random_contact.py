"""The pictures of a random-contact result folder, drawn by ParaView from its
first realisation (surface.vti):

  picture-gaps-K.png   the full-contact pressure less its mean (colour) with
                       the gaps of the boundary-element solution at the K-th
                       mean pressure (dark), one picture per load

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_random_contact.py RESULT_FOLDER [PNG_FOLDER]"""
import pathlib
import sys

import numpy
import paraview.simple as pv
from paraview import servermanager
from vtk.numpy_interface import dataset_adapter as dsa

folder = pathlib.Path(sys.argv[1])
pictures = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else folder
pictures.mkdir(parents=True, exist_ok=True)
size = [800, 700]
pressure = "full-contact pressure less its mean (Pa)"

surface = pv.XMLImageDataReader(FileName=[str(folder / "surface.vti")])
surface.UpdatePipeline()
data = dsa.WrapDataObject(servermanager.Fetch(surface))
gap_names = [name for name in data.PointData.keys() if name.startswith("gap at")]
if pressure not in data.PointData.keys() or not gap_names:
    sys.exit(f"{folder / 'surface.vti'} lacks the full-contact pressure or the gaps")
bounds = data.GetBounds()
side = max(bounds[1] - bounds[0], bounds[3] - bounds[2])

view = pv.CreateView("RenderView")
view.ViewSize = size
view.OrientationAxesVisibility = 0
view.CameraParallelProjection = 1
view.Background = [1, 1, 1]
view.UseColorPaletteForBackground = 0
centre = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2, 0]
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0], centre[1], 10 * side]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelScale = 0.62 * side

surface_display = pv.Show(surface, view)
surface_display.SetRepresentationType("Slice")
pv.ColorBy(surface_display, ("POINTS", pressure))
colours = pv.GetColorTransferFunction(pressure)
colours.ApplyPreset("Cool to Warm", True)
largest = numpy.abs(numpy.asarray(data.PointData[pressure])).max()
colours.RescaleTransferFunction(-largest, largest)
bar = pv.GetScalarBar(colours, view)
bar.Title, bar.ComponentTitle = "p_fc - mean (Pa)", ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
bar.WindowLocation = "Any Location"
bar.Position = [0.88, 0.1]
surface_display.SetScalarBarVisibility(view, True)

title = pv.Text()
title_display = pv.Show(title, view)
title_display.Color = [0, 0, 0]
title_display.WindowLocation = "Upper Center"
title_display.FontSize = 13

for k, name in enumerate(gap_names, start=1):
    share = (numpy.asarray(data.PointData[name]) > 0).mean()
    gaps = pv.Threshold(Input=surface, Scalars=["POINTS", name], LowerThreshold=1e-300, UpperThreshold=1e300)
    gaps_display = pv.Show(gaps, view)
    pv.ColorBy(gaps_display, None)
    gaps_display.AmbientColor = gaps_display.DiffuseColor = [0.1, 0.1, 0.1]
    gaps_display.Opacity = 0.75
    title.Text = (f"first realisation: full-contact pressure (colour), gaps (dark) {name[len('gap at '):-4]}: "
                  f"{share:.3f} of the points")
    pv.Render(view)
    pv.SaveScreenshot(str(pictures / f"picture-gaps-{k}.png"), view, ImageResolution=size)
    print(pictures / f"picture-gaps-{k}.png")
    pv.Hide(gaps, view)
