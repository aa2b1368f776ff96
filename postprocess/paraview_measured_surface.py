"""The pictures of a measured-surface result folder, drawn by ParaView from
its fields (surface.vti):

  picture-measured-gaps-K.png   at the K-th mean pressure, side by side, the
                                gaps of the map taken as one period (left)
                                and as an isolated patch (right), dark over
                                the prepared heights (colour)

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_measured_surface.py RESULT_FOLDER [PNG_FOLDER]"""
import sys

import numpy
import paraview.simple as pv

from paraview_common import (dark_where_positive, fetched, folders, save, side_by_side, symmetric_colours, title,
                             white_view)

folder, pictures = folders()
size = [1400, 700]
heights = "height (m)"

surface = pv.XMLImageDataReader(FileName=[str(folder / "surface.vti")])
data = fetched(surface)
names = data.PointData.keys()
periodic = [name for name in names if name.startswith("gap periodic at")]
if heights not in names or not periodic:
    sys.exit(f"{folder / 'surface.vti'} lacks the heights or the gaps (a run with Refinement = 1 writes them)")
view = white_view(size)
colours = symmetric_colours(heights, numpy.abs(numpy.asarray(data.PointData[heights])).max())
left, right = side_by_side(view, surface, data, heights, colours, "height (m)")
label = title(view, "")

for k, name in enumerate(periodic, start=1):
    load = name[len("gap periodic at "):-4]
    patch = "gap patch at " + load + " (m)"
    shown = [dark_where_positive(view, left, data, name), dark_where_positive(view, right, data, patch)]
    shares = [(numpy.asarray(data.PointData[field]) > 0).mean() for field in (name, patch)]
    label.Text = (f"gaps (dark) at {load}: the map as one period (left) {shares[0]:.3f}, "
                  f"as an isolated patch (right) {shares[1]:.3f} of the points")
    save(view, pictures / f"picture-measured-gaps-{k}.png", size)
    for gaps in shown:
        if gaps is not None:
            pv.Hide(gaps, view)
