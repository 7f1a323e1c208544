"""Opens impm's Exodus outputs in ParaView and checks what a user would look at.

Run with pvbatch (under a virtual X server: Debian's ParaView needs a display).  For every
file: the reader opens it, it has the expected time steps, points and cells, and the named
arrays; the displaced particle positions match the particle CSV; a PNG is rendered (2-D and
3-D gimp and cpdi runs: the deformed particle domains of <prefix>_domains.exo, warped by their
corner displacements; 3-D from an oblique viewpoint) with what a reader needs to use it: the time, a colour bar titled with
the field's name and units, and the grid's extent as an outline; the check asks the render
view for each of them, not only for a PNG.

usage: pvbatch check_outputs.py OUTPUT_DIR PREFIX PNG [OUTPUT_EVERY [COLOUR [WIDTHxHEIGHT
                                                                           [UNITS]]]]
(COLOUR: the element variable the picture is coloured by, stress_yy in 2-D and 3-D by
default; WIDTHxHEIGHT: the picture's size in pixels, 600x600 in 2-D and 3-D by default; UNITS: those of the
deck, for the colour bar's title, "deck units" by default: impm itself is unit-free)
"""

import csv
import os
import sys

from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction,
                             GetDisplayProperties, GetScalarBar, MergeBlocks,
                             OpenDataFile, Render, ResetCamera, SaveScreenshot, Show, Text)
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
dim = 3 if "Z" in table[0] else 2 if "Y" in table[0] else 1
two_d = dim == 2
axes = ("x", "y", "z")[:dim]

grid_reader, _, grid, grid_times = fetch(os.path.join(out_dir, prefix + "_grid.exo"))
every = int(sys.argv[4]) if len(sys.argv) > 4 else 1  # the run's Output/Every
steps = len(history) - 1
expected_times = 1 + steps // every + (1 if steps % every else 0)
check(len(grid_times) == expected_times, "grid file: %d time steps, expected %d (history: %d "
      "rows, output every %d)" % (len(grid_times), expected_times, len(history), every))
expected_cell = {1: 3, 2: 9, 3: 12}[dim]  # VTK_LINE, VTK_QUAD, VTK_HEXAHEDRON
check(grid.GetNumberOfCells() > 0 and grid.GetCellType(0) == expected_cell,
      "grid cells are not %s" % {1: "BAR2 lines", 2: "QUAD4 quadrilaterals",
                                 3: "HEX8 hexahedra"}[dim])
# Static and fixed-grid runs keep nodal displacements; moving-particle dynamics the grid
# velocity and mass of the last step.
grid_arrays = arrays(grid, "point")
# (ParaView joins displacementX, displacementY into a vector "displacement".)
check(any(n in grid_arrays for n in ("displacementX", "displacement", "velocityX", "velocity")),
      "grid file has neither a displacement nor a velocity: %s" % grid_arrays)

reader, merged, particles, times = fetch(os.path.join(out_dir, prefix + "_particles.exo"))
check(particles.GetNumberOfPoints() == len(table),
      "%d particles in Exodus, %d in the CSV" % (particles.GetNumberOfPoints(), len(table)))
check(particles.GetCellType(0) == 1, "particles are not vertex cells")
names = {1: ("strain", "stress", "volume", "mass"),
         2: ("stress_xx", "stress_yy", "stress_xy", "J", "volume", "mass"),
         3: ("stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz", "J",
             "volume", "mass")}[dim]
for name in names:
    check(name in arrays(particles, "cell"), "particle file has no " + name)
# ParaView applies the displacement: the points are the current positions of the CSV.
for p in range(0, len(table), max(1, len(table) // 7)):
    for d, column in enumerate(axes):
        x = particles.GetPoint(p)[d]
        check(abs(x - float(table[p][column])) < 1e-9 * max(1.0, abs(x)),
              "particle %d drawn at %s = %g, CSV says %s" % (p, column, x, table[p][column]))

shown, colour, representation = merged, "stress", "Points"
domains_path = os.path.join(out_dir, prefix + "_domains.exo")
if dim > 1:
    colour = sys.argv[5] if len(sys.argv) > 5 else "stress_yy"
    if os.path.exists(domains_path):
        _, domains_merged, domains, domain_times = fetch(domains_path)
        check(domains.GetNumberOfCells() == len(table) and domains.GetCellType(0) == expected_cell,
              "domain file: %d cells (type %d) for %d particles"
              % (domains.GetNumberOfCells(), domains.GetCellType(0), len(table)))
        check(len(domain_times) == len(times), "domain file and particle file time steps differ")
        shown, representation = domains_merged, "Surface With Edges"

view = CreateView("RenderView")
view.ViewSize = ([int(n) for n in sys.argv[6].split("x")] if len(sys.argv) > 6 else
                 [600, 600] if dim > 1 else [800, 300])
view.ViewTime = times[-1]
display = Show(shown, view)
ColorBy(display, ("CELLS", colour))
display.RescaleTransferFunctionToDataRange(True)
if len(sys.argv) > 5:  # a chosen field: its range up to the 95th percentile
    values = sorted(float(p[colour]) for p in table if colour in p)
    if values and values[int(0.95 * (len(values) - 1))] > values[0]:
        GetColorTransferFunction(colour).RescaleTransferFunction(
            values[0], values[int(0.95 * (len(values) - 1))])
    representation = "Surface"
# What a reader needs: the field and its units on a colour bar, the time, the grid's extent.
units = sys.argv[7] if len(sys.argv) > 7 else "deck units"
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(GetColorTransferFunction(colour), view)
bar.Title, bar.ComponentTitle = colour, "(%s)" % units
clock = Text(Text="t = %.4g" % times[-1])
clock_display = Show(clock, view)
clock_display.WindowLocation = "Upper Left Corner"
outline = Show(MergeBlocks(Input=grid_reader), view)
outline.SetRepresentationType("Outline")
outline.AmbientColor = outline.DiffuseColor = [0.85, 0.85, 0.85]
display.SetRepresentationType(representation)
display.PointSize = 6
view.CameraParallelProjection = 1 if two_d else 0
ResetCamera(view)
if two_d:  # fit the grid, outlined (not its bounding sphere), to the picture
    x0, x1, y0, y1, _, _ = grid.GetBounds()
    width, height = view.ViewSize
    view.CameraFocalPoint = [(x0 + x1) / 2, (y0 + y1) / 2, 0.0]
    view.CameraPosition = [(x0 + x1) / 2, (y0 + y1) / 2, 10.0 * max(x1 - x0, y1 - y0)]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = 0.55 * max(y1 - y0, (x1 - x0) * height / width)
if dim == 3:  # from the front, right and above, the y axis up, the whole grid in sight
    x0, x1, y0, y1, z0, z1 = grid.GetBounds()
    centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
    size = max(x1 - x0, y1 - y0, z1 - z0)
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 1.5 * size, centre[1] + 1.2 * size, centre[2] + 2.8 * size]
    view.CameraViewUp = [0.0, 1.0, 0.0]
Render(view)
SaveScreenshot(png, view)
check(os.path.getsize(png) > 1000, "the rendered picture is empty")
# The annotations are in the picture: the view holds them, visible.
check(bar.Visibility == 1 and bar.Title == colour and units in bar.ComponentTitle,
      "no colour bar titled %s (%s)" % (colour, units))
check(clock_display.Visibility == 1 and clock.Text.startswith("t = "), "no time in the picture")
check(outline.Visibility == 1 and outline.Representation == "Outline",
      "no outline of the grid in the picture")

for f in failures:
    print("FAIL:", f)
print("checked %s: %d particles, %d time steps" % (prefix, len(table), len(times)))
sys.stdout.flush()
# Leave without ParaView's teardown, which fails under Xvfb with GLXBadContext after all
# the work is done.
os._exit(1 if failures else 0)
