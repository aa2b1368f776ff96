"""The pictures of an adhesive-random-contact result folder, drawn by ParaView
from its first realisation on the finest cohesive zone (surface.vti):

  picture-adhesive-gaps-K.png   at the K-th mean pressure, side by side, the
                                gaps without adhesion (left) and with it on the
                                loading branch (right), dark over the
                                full-contact pressure less its mean (colour);
                                at p_bar = 0 there is no contact without
                                adhesion, and the left is empty

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_adhesive_contact.py RESULT_FOLDER [PNG_FOLDER]"""
import sys

import numpy
import paraview.simple as pv

from paraview_common import (colour_bar, fetched, folders, look_at, save, symmetric_colours, title,
                             white_view)

folder, pictures = folders()
size = [1400, 700]
pressure = "full-contact pressure less its mean (Pa)"

surface = pv.XMLImageDataReader(FileName=[str(folder / "surface.vti")])
data = fetched(surface)
names = data.PointData.keys()
adhesive = [name for name in names if name.startswith("gap with adhesion at")]
if pressure not in names or not adhesive:
    sys.exit(f"{folder / 'surface.vti'} lacks the full-contact pressure or the adhesive gaps")
x0, x1, y0, y1 = data.GetBounds()[:4]
side = max(x1 - x0, y1 - y0)
shift = 1.08 * side

view = white_view(size)
left = surface
right = pv.Transform(Input=surface)
right.Transform.Translate = [shift, 0, 0]
colours = symmetric_colours(pressure, numpy.abs(numpy.asarray(data.PointData[pressure])).max())
for source in (left, right):
    display = pv.Show(source, view)
    display.SetRepresentationType("Slice")
    pv.ColorBy(display, ("POINTS", pressure))
colour_bar(view, display, colours, "p_fc - mean (Pa)", [0.93, 0.1])
label = title(view, "")
look_at(view, [(x0 + x1 + shift) / 2, (y0 + y1) / 2, 0], 0.58 * side, 10 * side)


def dark_gaps(source, name):
    """The points of `source` where the field `name` (a gap) is positive, dark and half transparent."""
    gaps = pv.Threshold(Input=source, Scalars=["POINTS", name], LowerThreshold=1e-300, UpperThreshold=1e300)
    display = pv.Show(gaps, view)
    pv.ColorBy(display, None)
    display.AmbientColor = display.DiffuseColor = [0.1, 0.1, 0.1]
    display.Opacity = 0.75
    return gaps


for k, name in enumerate(adhesive, start=1):
    load = name[len("gap with adhesion at "):-4]
    without = "gap without adhesion at " + load + " (m)"
    shown = [dark_gaps(right, name)]
    share = (numpy.asarray(data.PointData[name]) > 0).mean()
    text = f"with adhesion (right): {share:.3f} of the points"
    if without in names:
        shown.append(dark_gaps(left, without))
        text = (f"without adhesion (left): {(numpy.asarray(data.PointData[without]) > 0).mean():.3f}, "
                + text)
    else:
        text = "without adhesion (left): no contact; " + text
    label.Text = f"first realisation, gaps (dark, gap > 0) at {load}: {text}"
    save(view, pictures / f"picture-adhesive-gaps-{k}.png", size)
    for gaps in shown:
        pv.Hide(gaps, view)
