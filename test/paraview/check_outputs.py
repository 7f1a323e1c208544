"""Opens impm's Exodus outputs in ParaView and checks what a user would look at.

Run with pvbatch (under a virtual X server: Debian's ParaView needs a display).  For every
file: the reader opens it, it has the expected time steps, points and cells, and the named
arrays; the displaced particle positions match the particle CSV; a PNG is rendered.

usage: pvbatch check_outputs.py OUTPUT_DIR PREFIX PNG
"""

import csv
import os
import sys

from paraview.simple import (ColorBy, CreateView, GetDisplayProperties, MergeBlocks,
                             OpenDataFile, Render, ResetCamera, SaveScreenshot, Show)
from paraview import servermanager

out_dir, prefix, png = sys.argv[1], sys.argv[2], sys.argv[3]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def fetch(path):
    reader = OpenDataFile(path)
    check(reader is not None, "ParaView cannot open " + path)
    times = list(reader.TimestepValues)
    merged = MergeBlocks(Input=reader)
    merged.UpdatePipeline(time=times[-1])
    return reader, merged, servermanager.Fetch(merged), times


def arrays(data, kind):
    fields = data.GetPointData() if kind == "point" else data.GetCellData()
    return [fields.GetArrayName(i) for i in range(fields.GetNumberOfArrays())]


with open(os.path.join(out_dir, prefix + "_particles.csv")) as f:
    table = list(csv.DictReader(f))
history = list(csv.DictReader(open(os.path.join(out_dir, prefix + "_history.csv"))))

grid_reader, _, grid, grid_times = fetch(os.path.join(out_dir, prefix + "_grid.exo"))
check(len(grid_times) == len(history), "grid file: %d time steps, history: %d rows"
      % (len(grid_times), len(history)))
check(grid.GetNumberOfCells() > 0 and grid.GetCellType(0) == 3, "grid cells are not BAR2 lines")
check("displacementX" in arrays(grid, "point"), "grid file has no displacementX")

reader, merged, particles, times = fetch(os.path.join(out_dir, prefix + "_particles.exo"))
check(particles.GetNumberOfPoints() == len(table),
      "%d particles in Exodus, %d in the CSV" % (particles.GetNumberOfPoints(), len(table)))
check(particles.GetCellType(0) == 1, "particles are not vertex cells")
for name in ("strain", "stress", "volume", "mass"):
    check(name in arrays(particles, "cell"), "particle file has no " + name)
# ParaView applies displacementX: the points are the current positions x of the CSV.
for p in range(0, len(table), max(1, len(table) // 7)):
    x = particles.GetPoint(p)[0]
    check(abs(x - float(table[p]["x"])) < 1e-9 * max(1.0, abs(x)),
          "particle %d drawn at %g, CSV says x = %s" % (p, x, table[p]["x"]))

view = CreateView("RenderView")
view.ViewSize = [800, 300]
view.ViewTime = times[-1]
display = Show(merged, view)
ColorBy(display, ("CELLS", "stress"))
display.RescaleTransferFunctionToDataRange(True)
display.SetRepresentationType("Points")
display.PointSize = 6
ResetCamera(view)
Render(view)
SaveScreenshot(png, view)
check(os.path.getsize(png) > 1000, "the rendered picture is empty")

for f in failures:
    print("FAIL:", f)
print("checked %s: %d particles, %d time steps" % (prefix, len(table), len(times)))
sys.stdout.flush()
# Leave without ParaView's teardown, which fails under Xvfb with GLXBadContext after all
# the work is done.
os._exit(1 if failures else 0)
