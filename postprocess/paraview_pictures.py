"""The standard pictures of a penny-gap result folder, drawn by ParaView from
the tip-frame fields (solution-tip.vtu, coordinates (r - c)/c and z/c):

  picture-von-mises.png          von Mises stress on a log scale near the gap
  picture-sigma-zz-1e-2.png      sigma_zz at the tip with the mesh, window 1e-2 c
  picture-sigma-zz-1e-6.png      the same, window 1e-6 c (when the mesh reaches it)
  picture-opening.png            the gap warped, beside the FE opening u_z(r) and
                                 Sneddon's w(r) from opening.csv

Usage (ParaView's Python, offscreen under Xvfb):
  xvfb-run -a pvpython postprocess/paraview_pictures.py RESULT_FOLDER [PNG_FOLDER]"""
import csv

import numpy
import paraview.simple as pv
from paraview import servermanager
from vtk.numpy_interface import dataset_adapter as dsa

from paraview_common import folders, white_view

folder, pictures = folders()
size = [900, 600]

fields = pv.XMLUnstructuredGridReader(FileName=[str(folder / "solution-tip.vtu")])
fields.UpdatePipeline()
view = white_view(size)


def frame(source, half_width, height, title):
    """Shows `source` with labelled axes, the window [-half_width, half_width] x
    [0, height] on the left four fifths of the picture (the colour bar on the right)."""
    display = pv.Show(source, view)
    grid = display.DataAxesGrid
    grid.GridAxesVisibility = 1
    grid.UseCustomBounds = 1
    grid.CustomBounds = [-half_width, half_width, 0, height, 0, 0]
    grid.XTitle, grid.YTitle = "(r - c)/c", "z/c"
    for axis in ("X", "Y"):
        setattr(grid, axis + "TitleColor", [0, 0, 0])
        setattr(grid, axis + "LabelColor", [0, 0, 0])
    grid.GridColor = [0, 0, 0]
    per_pixel = max(2.5 * half_width / (0.75 * size[0]), 1.5 * height / size[1])
    focal = [0.12 * size[0] * per_pixel, height / 2, 0]
    view.CameraFocalPoint = focal
    view.CameraPosition = [focal[0], focal[1], 10 * half_width]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = 0.5 * size[1] * per_pixel
    title_text = pv.Text(Text=title)
    title_display = pv.Show(title_text, view)
    title_display.Color = [0, 0, 0]
    title_display.WindowLocation = "Upper Center"
    title_display.FontSize = 14
    return display, title_text


def visible_range(source, array, half_width):
    """The range of `array` over the points at least half_width/50 from the tip:
    the tip's singular values would wash out the colours of the rest."""
    data = dsa.WrapDataObject(servermanager.Fetch(source))
    points = numpy.asarray(data.Points)
    far = numpy.hypot(points[:, 0], points[:, 1]) > half_width / 50
    values = numpy.asarray(data.PointData[array])[far]
    return values.min(), values.max()


def color(display, array, log_scale=False, value_range=None):
    """Colours by `array` over `value_range` (by default the range of all fields)."""
    pv.ColorBy(display, ("POINTS", array))
    lut = pv.GetColorTransferFunction(array)
    low, high = value_range or fields.PointData[array].GetRange()
    if log_scale:
        low = max(low, high * 1e-6)
        lut.UseLogScale = 1
    lut.RescaleTransferFunction(low, high)
    bar = pv.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = array + " (Pa)", ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Position = [0.87, 0.12]
    bar.ScalarBarLength = 0.7
    display.SetScalarBarVisibility(view, True)


def save(name):
    pv.Render(view)
    pv.SaveScreenshot(str(pictures / name), view, ImageResolution=size)
    print(pictures / name)


def clear():
    for source in list(pv.GetSources().values()):
        pv.Hide(source, view)


# 1. von Mises on a log scale over the gap and around the tip.
display, title = frame(fields, 1.0, 1.0, "von Mises stress, log scale (tip frame, units of c)")
color(display, "von_mises", log_scale=True, value_range=visible_range(fields, "von_mises", 1.0))
save("picture-von-mises.png")
clear()

# 2. sigma_zz at the tip with the mesh, in windows of 1e-2 c and 1e-6 c. Each
# window is scaled to unit size for drawing (VTK's axes misbehave at 1e-6).
for exponent in (2, 6):
    width = 10.0 ** -exponent
    window = pv.ExtractCellsByRegion(Input=fields, IntersectWith="Box")
    window.IntersectWith.Position = [-width, 0, -1]
    window.IntersectWith.Length = [2 * width, width, 2]
    window.Extractintersected = 1
    window.UpdatePipeline()
    if window.GetDataInformation().GetNumberOfCells() == 0:
        print(f"no cells within 1e-{exponent} c of the tip: picture skipped")
        continue
    scaled = pv.Transform(Input=window)
    scaled.Transform.Scale = [1 / width, 1 / width, 1]
    display, title = frame(scaled, 1.0, 1.0, f"sigma_zz at the tip with the mesh, window 1e-{exponent} c")
    grid = display.DataAxesGrid
    grid.XTitle, grid.YTitle = f"(r - c)/c  x 1e{exponent}", f"z/c  x 1e{exponent}"
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [0, 0, 0]
    color(display, "sigma_zz", value_range=visible_range(scaled, "sigma_zz", 1.0))
    save(f"picture-sigma-zz-1e-{exponent}.png")
    clear()

# 3. The opening: the gap warped (magnified), beside u_z(r) and the exact w(r).
u_z_range = fields.PointData["u_z"].GetRange()
magnification = 0.1 / max(abs(u_z_range[0]), abs(u_z_range[1]))
warped = pv.WarpByVector(Input=fields, Vectors=["POINTS", "u"], ScaleFactor=magnification)
display, title = frame(warped, 1.0, 1.0, "")
display.SetRepresentationType("Surface With Edges")
display.EdgeColor = [0.3, 0.3, 0.3]
color(display, "sigma_zz", value_range=visible_range(fields, "sigma_zz", 1.0))
pv.Render(view)
pv.SaveScreenshot(str(pictures / "warped.png"), view, ImageResolution=size)

import matplotlib  # noqa: E402  (ParaView first: it sets up its own rendering)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

with open(folder / "opening.csv") as table:
    rows = [{key: float(value) for key, value in row.items()} for row in csv.DictReader(table)]
figure, (left, right) = plt.subplots(1, 2, figsize=(13, 4.8), gridspec_kw={"width_ratios": [1.4, 1]})
left.imshow(plt.imread(str(pictures / "warped.png")))
left.set_axis_off()
left.set_title(f"the gap opened, displacement magnified {magnification:.3g} / c (colour: sigma_zz)")
r = [row["r/c"] for row in rows]
right.plot(r, [row["w exact (m)"] for row in rows], "k-", label="Sneddon's w(r)")
right.plot(r, [row["w FE (m)"] for row in rows], "o", mfc="none", color="tab:red", ms=4, label="FE u_z on the face")
right.set_xlabel("r/c")
right.set_ylabel("opening of one face (m)")
right.grid(alpha=0.3)
right.legend()
figure.tight_layout()
figure.savefig(pictures / "picture-opening.png", dpi=100)
(pictures / "warped.png").unlink()
print(pictures / "picture-opening.png")
