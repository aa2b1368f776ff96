#!/usr/bin/env bash
# Usage: check_paraview.sh PENNY SCENE.prm PICTURE_SCRIPT RESULT_FOLDER PNG...
# Runs a scene that writes fields into RESULT_FOLDER, draws its ParaView
# pictures with pvpython under Xvfb, and checks that each PNG is written and
# not blank (many distinct colours, no single colour covering it).
set -eu
penny=$1 scene=$2 script=$3 results=$4
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$penny" "$scene" > /dev/null
# Xvfb now and then fails to give pvpython a window when the suite runs
# tests in parallel (ParaView aborts in vtkXOpenGLRenderWindow::CreateAWindow;
# seen twice in about fifteen runs): up to three tries, each reported.
for attempt in 1 2 3; do
  if timeout 300 xvfb-run -a -e xvfb.log -s "-screen 0 1280x1024x24" pvpython "$script" "$results" pictures \
    > pictures.log 2>&1; then
    break
  fi
  echo "pvpython try $attempt failed:"
  grep -m 5 -E "ERR|FATL|error|Error" pictures.log xvfb.log || tail -5 pictures.log
  [ $attempt -lt 3 ] || { echo "FAIL: pvpython"; exit 1; }
done
/usr/bin/python3 - pictures "$@" <<'PY'
import pathlib
import sys

import matplotlib.image
import numpy

folder = pathlib.Path(sys.argv[1])
for name in sys.argv[2:]:
    path = folder / name
    assert path.is_file(), f"{name} was not written"
    pixels = matplotlib.image.imread(str(path))[:, :, :3].reshape(-1, 3)
    colours, counts = numpy.unique((pixels * 255).astype(int), axis=0, return_counts=True)
    assert len(colours) > 100, f"{name}: only {len(colours)} colours"
    assert counts.max() < 0.9 * len(pixels), f"{name}: one colour covers {counts.max() / len(pixels):.0%}"
    print(f"ok: {name}, {len(colours)} colours")
PY
