"""The pictures of a random-contact result folder, drawn by ParaView from its
first realisation (surface.vti):

  picture-gaps-K.png   the full-contact pressure less its mean (colour) with
                       the gaps of the boundary-element solution at the K-th
                       mean pressure (dark), one picture per load

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_random_contact.py RESULT_FOLDER [PNG_FOLDER]"""
import sys

import numpy
import paraview.simple as pv

from paraview_common import (colour_bar, fetched, folders, look_at, save, symmetric_colours, title,
                             white_view)

folder, pictures = folders()
size = [800, 700]
pressure = "full-contact pressure less its mean (Pa)"

surface = pv.XMLImageDataReader(FileName=[str(folder / "surface.vti")])
data = fetched(surface)
gap_names = [name for name in data.PointData.keys() if name.startswith("gap at")]
if pressure not in data.PointData.keys() or not gap_names:
    sys.exit(f"{folder / 'surface.vti'} lacks the full-contact pressure or the gaps")
x0, x1, y0, y1 = data.GetBounds()[:4]
side = max(x1 - x0, y1 - y0)

view = white_view(size)
surface_display = pv.Show(surface, view)
surface_display.SetRepresentationType("Slice")
pv.ColorBy(surface_display, ("POINTS", pressure))
colours = symmetric_colours(pressure, numpy.abs(numpy.asarray(data.PointData[pressure])).max())
colour_bar(view, surface_display, colours, "p_fc - mean (Pa)", [0.88, 0.1])
label = title(view, "")
look_at(view, [(x0 + x1) / 2, (y0 + y1) / 2, 0], 0.62 * side, 10 * side)

for k, name in enumerate(gap_names, start=1):
    share = (numpy.asarray(data.PointData[name]) > 0).mean()
    gaps = pv.Threshold(Input=surface, Scalars=["POINTS", name], LowerThreshold=1e-300, UpperThreshold=1e300)
    gaps_display = pv.Show(gaps, view)
    pv.ColorBy(gaps_display, None)
    gaps_display.AmbientColor = gaps_display.DiffuseColor = [0.1, 0.1, 0.1]
    gaps_display.Opacity = 0.75
    label.Text = (f"first realisation: full-contact pressure (colour), gaps (dark) {name[len('gap at '):-4]}: "
                  f"{share:.3f} of the points")
    save(view, pictures / f"picture-gaps-{k}.png", size)
    pv.Hide(gaps, view)
