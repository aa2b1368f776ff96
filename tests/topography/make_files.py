"""Writes the small topography files of the tests, one per format, each from its
public specification (not by penny): 6 x 4 points, pixels 0.5 um (x) by
0.25 um (y), heights h(i, j) = 0.5 nm k(i, j) with k = i^2 - 3 j + i j, each
file in units of its own; the point (i, j) = (2, 1) is marked as not measured
in the files marked "missing".  Usage: /usr/bin/python3 make_files.py FOLDER"""
import io
import pathlib
import struct
import sys
import zipfile

import numpy as np
from scipy.io import netcdf_file

NX, NY, DX, DY = 6, 4, 0.5e-6, 0.25e-6
k = np.array([[i * i - 3 * j + i * j for j in range(NY)] for i in range(NX)], dtype=float)  # k[i, j]
heights = 0.5e-9 * k  # metres
missing = (2, 1)
folder = pathlib.Path(sys.argv[1])

# Matrix text with a Gwyddion header: a row per y, a column per x, heights in nm.
rows = ["# Channel: test", "# Width: 3 um", "# Height: 1000 nm", "# Value units: nm"]
rows += ["\t".join(f"{heights[i, j] * 1e9:.17g}" for i in range(NX)) for j in range(NY)]
(folder / "matrix.txt").write_text("\n".join(rows) + "\n")
rows[4 + missing[1]] = "\t".join("nan" if i == missing[0] else f"{heights[i, missing[1]] * 1e9:.17g}"
                                  for i in range(NX))
(folder / "matrix-missing.txt").write_text("\n".join(rows) + "\n")

# xyz text in um, in a shuffled order, without the missing point.
points = [(i * DX * 1e6, j * DY * 1e6, heights[i, j] * 1e6) for i in range(NX) for j in range(NY)
          if (i, j) != missing]
np.random.default_rng(1).shuffle(points)
(folder / "missing.xyz").write_text("".join(f"{x:.17g} {y:.17g} {z:.17g}\n" for x, y, z in points))


# ISO 25178-72: main.xml and little-endian heights, x the fast index.
def x3p(path, data_type, increment, values, valid=None):
    z_axis = f"<DataType>{data_type}</DataType>"
    if increment is not None:
        z_axis += f"<Increment>{increment!r}</Increment><Offset>0</Offset>"
    valid_link = "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>" if valid is not None else ""
    xml = f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>
<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{DX!r}</Increment><Offset>0</Offset></CX>
<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{DY!r}</Increment><Offset>0</Offset></CY>
<CZ><AxisType>A</AxisType>{z_axis}</CZ></Axes></Record1>
<Record2><Instrument><Manufacturer>penny tests</Manufacturer><Model>make_files.py</Model></Instrument></Record2>
<Record3><MatrixDimension><SizeX>{NX}</SizeX><SizeY>{NY}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
<DataLink><PointDataLink>bindata/data.bin</PointDataLink>{valid_link}</DataLink></Record3>
</p:ISO5436_2>
"""
    code = {"I": "<i2", "L": "<i4", "F": "<f4", "D": "<f8"}[data_type]
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("main.xml", xml)
        archive.writestr("bindata/data.bin", np.ascontiguousarray(values.T).astype(code).tobytes())
        if valid is not None:
            archive.writestr("bindata/valid.bin", np.packbits(valid.T.ravel(), bitorder="little").tobytes())


x3p(folder / "doubles.x3p", "D", None, heights)
valid = np.ones((NX, NY), dtype=np.uint8)
valid[missing] = 0
x3p(folder / "integers-missing.x3p", "I", 0.5e-9, k, valid)


# Digital Surf .sur: the 512-byte header, then 32-bit integers in nm steps of 0.5, x the fast index.
def sur(path, raw, special):
    header = bytearray(512)
    header[0:12] = b"DIGITAL SURF"
    struct.pack_into("<HHHH", header, 12, 0, 1, 1, 2)  # format, objects, version, type (surface)
    header[50:80] = b"make_files.py".ljust(30)
    struct.pack_into("<H", header, 86, special)
    struct.pack_into("<H", header, 98, 32)
    struct.pack_into("<iiiiI", header, 100, int(k.min()), int(k.max()), NX, NY, NX * NY)
    struct.pack_into("<fff", header, 120, 500.0, 250.0, 0.5)  # spacings in nm, Z step in nm
    for offset, unit in zip(range(132, 276, 16), [b"X", b"Y", b"Z", b"nm", b"nm", b"nm", b"um", b"um", b"nm"]):
        header[offset:offset + 16] = unit.ljust(16)
    struct.pack_into("<fff", header, 276, 1.0, 1.0, 1.0)
    path.write_bytes(bytes(header) + np.ascontiguousarray(raw.T).astype("<i4").tobytes())


sur(folder / "heights.sur", k, 0)
marked = k.copy()
marked[missing] = k.min() - 2
sur(folder / "missing.sur", marked, 1)

# ContactEngineering's NetCDF: heights(x, y) in um, the lengths in um, a mask.
with netcdf_file(folder / "missing.nc", "w") as nc:
    nc.createDimension("x", NX)
    nc.createDimension("y", NY)
    for axis, n, d in (("x", NX, DX), ("y", NY, DY)):
        variable = nc.createVariable(axis, "d", (axis,))
        variable[:] = np.arange(n) * d * 1e6
        variable.length = n * d * 1e6
        variable.unit = "um"
    variable = nc.createVariable("heights", "d", ("x", "y"))
    variable[:, :] = heights * 1e6
    variable.unit = "um"
    mask = nc.createVariable("mask", "i", ("x", "y"))
    mask[:, :] = 0
    mask[missing] = 1
