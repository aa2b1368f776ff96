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

from paraview_common import (dark_where_positive, fetched, folders, save, side_by_side, symmetric_colours, title,
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
view = white_view(size)
colours = symmetric_colours(pressure, numpy.abs(numpy.asarray(data.PointData[pressure])).max())
left, right = side_by_side(view, surface, data, pressure, colours, "p_fc - mean (Pa)")
label = title(view, "")

for k, name in enumerate(adhesive, start=1):
    load = name[len("gap with adhesion at "):-4]
    without = "gap without adhesion at " + load + " (m)"
    shown = [dark_where_positive(view, right, data, name)]
    share = (numpy.asarray(data.PointData[name]) > 0).mean()
    text = f"with adhesion (right): {share:.3f} of the points"
    if without in names:
        shown.append(dark_where_positive(view, left, data, without))
        text = (f"without adhesion (left): {(numpy.asarray(data.PointData[without]) > 0).mean():.3f}, "
                + text)
    else:
        text = "without adhesion (left): no contact; " + text
    label.Text = f"first realisation, gaps (dark, gap > 0) at {load}: {text}"
    save(view, pictures / f"picture-adhesive-gaps-{k}.png", size)
    for gaps in shown:
        if gaps is not None:
            pv.Hide(gaps, view)
