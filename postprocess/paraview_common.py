"""What the ParaView picture scripts share: their arguments, a white
parallel-projection view, colour bars and titles, and the data of a source
as numpy arrays. For pvpython (ParaView's Python), offscreen under Xvfb."""
import pathlib
import sys

import numpy
import paraview.simple as pv
from paraview import servermanager
from vtk.numpy_interface import dataset_adapter as dsa


def folders():
    """RESULT_FOLDER [PNG_FOLDER] from the command line (PNG_FOLDER made if new)."""
    if len(sys.argv) not in (2, 3):
        sys.exit(f"usage: pvpython {sys.argv[0]} RESULT_FOLDER [PNG_FOLDER]")
    folder = pathlib.Path(sys.argv[1])
    pictures = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else folder
    pictures.mkdir(parents=True, exist_ok=True)
    return folder, pictures


def white_view(size):
    """A render view of `size` pixels: white, parallel projection, no axes triad."""
    view = pv.CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.CameraParallelProjection = 1
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    return view


def look_at(view, centre, half_height, distance):
    """The camera above `centre` looking down -z, `half_height` of the scene
    in half the view's height. A first render resets the camera, so it is done first."""
    pv.Render(view)
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1], centre[2] + distance]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = half_height


def colour_bar(view, display, lut, title, position):
    """The colour bar of `lut` for `display`, black text, at `position` (view fractions)."""
    bar = pv.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = title, ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Position = position
    display.SetScalarBarVisibility(view, True)
    return bar


def symmetric_colours(name, largest):
    """The 'Cool to Warm' colour map of the field `name` over [-largest, largest]: white at zero."""
    colours = pv.GetColorTransferFunction(name)
    colours.ApplyPreset("Cool to Warm", True)
    colours.RescaleTransferFunction(-largest, largest)
    return colours


def mesh_coloured_by_component(view, source, component, edge_grey, title, position):
    """`source` drawn with its cell edges, coloured by component 0, 1 or 2 of
    the displacement u over its range, with a colour bar."""
    display = pv.Show(source, view)
    display.SetRepresentationType("Surface With Edges")
    display.EdgeColor = [edge_grey] * 3
    pv.ColorBy(display, ("POINTS", "u", "XYZ"[component]))
    lut = pv.GetColorTransferFunction("u")
    lut.VectorMode = "Component"
    lut.VectorComponent = component
    lut.RescaleTransferFunction(*source.PointData["u"].GetRange(component))
    colour_bar(view, display, lut, title, position)
    return lut


def side_by_side(view, source, data, field, colours, bar_title):
    """`source` (whose fetched data is `data`) twice in `view`, left and right
    (a copy shifted by 1.08 of its larger side), both coloured by `field`
    with the colour map `colours`; the camera on both. Returns the two sources."""
    x0, x1, y0, y1 = data.GetBounds()[:4]
    side = max(x1 - x0, y1 - y0)
    right = pv.Transform(Input=source)
    right.Transform.Translate = [1.08 * side, 0, 0]
    for shown in (source, right):
        display = pv.Show(shown, view)
        display.SetRepresentationType("Slice")
        pv.ColorBy(display, ("POINTS", field))
        # Unlit: the shifted copy is no image any more, and lighting would grey it.
        display.Ambient, display.Diffuse = 1.0, 0.0
    colour_bar(view, display, colours, bar_title, [0.93, 0.1])
    look_at(view, [(x0 + x1 + 1.08 * side) / 2, (y0 + y1) / 2, 0], 0.58 * side, 10 * side)
    return source, right


def dark_where_positive(view, source, data, field):
    """The points of `source` (whose fetched data is `data`) where `field` (a
    gap) is positive, dark and half transparent; None where there are none
    (ParaView cannot colour an empty threshold)."""
    if not (numpy.asarray(data.PointData[field]) > 0).any():
        return None
    positive = pv.Threshold(Input=source, Scalars=["POINTS", field], LowerThreshold=1e-300, UpperThreshold=1e300)
    display = pv.Show(positive, view)
    pv.ColorBy(display, None)
    display.AmbientColor = display.DiffuseColor = [0.1, 0.1, 0.1]
    display.Opacity = 0.75
    return positive


def title(view, text, font_size=13):
    """A black title at the top of the view; its text can be changed later."""
    label = pv.Text(Text=text)
    display = pv.Show(label, view)
    display.Color = [0, 0, 0]
    display.WindowLocation = "Upper Center"
    display.FontSize = font_size
    return label


def fetched(source):
    """The data of `source` (updated), wrapped for numpy access."""
    source.UpdatePipeline()
    return dsa.WrapDataObject(servermanager.Fetch(source))


def save(view, path, size):
    pv.Render(view)
    pv.SaveScreenshot(str(path), view, ImageResolution=size)
    print(path)
