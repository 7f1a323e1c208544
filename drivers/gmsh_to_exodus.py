#!/usr/bin/env python3
"""Converts a 2-D Gmsh mesh (.msh, version 4, ASCII or binary) into the Exodus II body mesh
impm reads (Shape = mesh).  meshio (python3-meshio) reads the file; impm_mesh writes the
Exodus file through the exodusII library.

- every physical surface becomes an element block of its triangles and quadrilaterals,
  named as the physical group (elements in no physical surface are left out, as Gmsh
  itself leaves them out of a mesh with physical groups);
- every physical curve becomes a side set of the element edges its line segments lie on;
- elements are renumbered counter-clockwise where Gmsh numbered them clockwise.

    gmsh_to_exodus.py IN.msh OUT.exo [--mesher build/drivers/impm_mesh]
"""

import argparse
import os
import subprocess
import sys
import tempfile

import meshio

KINDS = {"triangle": ("TRI3", 3), "quad": ("QUAD4", 4)}


def physical_names(mesh):
    """{(dimension, tag): name} of the physical groups."""
    return {(int(d), int(t)): name for name, (t, d) in
            ((n, v[:2]) for n, v in mesh.field_data.items())}


def counter_clockwise(points, nodes):
    area = 0.0
    for k in range(len(nodes)):
        (x0, y0), (x1, y1) = points[nodes[k]][:2], points[nodes[(k + 1) % len(nodes)]][:2]
        area += x0 * y1 - x1 * y0
    return list(nodes) if area > 0 else list(reversed(nodes))


def convert(mesh):
    """(blocks, side sets): [(name, type, [nodes])], [(name, [(element, side)])], 0-based."""
    names = physical_names(mesh)
    tags = mesh.cell_data.get("gmsh:physical")
    if tags is None:
        sys.exit("gmsh_to_exodus: the mesh has no physical groups (name its surfaces and curves)")
    surfaces, curves = {}, {}
    for block, physical in zip(mesh.cells, tags):
        for cell, tag in zip(block.data, physical):
            if block.type in KINDS:
                name = names.get((2, int(tag)), str(int(tag)))
                surfaces.setdefault((name, block.type), []).append(
                    counter_clockwise(mesh.points, cell))
            elif block.type == "line":
                name = names.get((1, int(tag)), str(int(tag)))
                curves.setdefault(name, []).append(tuple(sorted(cell)))
    if not surfaces:
        sys.exit("gmsh_to_exodus: no triangle or quadrilateral lies in a physical surface")
    blocks = [(name, KINDS[kind][0], cells) for (name, kind), cells in sorted(surfaces.items())]
    edges = {}  # sorted node pair -> (element, Exodus side), 1-based
    element = 0
    for _, _, cells in blocks:
        for cell in cells:
            element += 1
            for k in range(len(cell)):
                edges[tuple(sorted((cell[k], cell[(k + 1) % len(cell)])))] = (element, k + 1)
    sides = []
    for name, segments in sorted(curves.items()):
        found = [edges[s] for s in segments if s in edges]
        if len(found) != len(segments):
            sys.exit("gmsh_to_exodus: physical curve '%s' has segments on no element edge" % name)
        sides.append((name, found))
    return blocks, sides


def write_text(path, points, blocks, sides):
    with open(path, "w") as f:
        f.write("nodes %d\n" % len(points))
        for p in points:
            f.write("%.17g %.17g\n" % (p[0], p[1]))
        for name, kind, cells in blocks:
            f.write("block %s %s %d\n" % (name.replace(" ", "_"), kind, len(cells)))
            for c in cells:
                f.write(" ".join(str(n + 1) for n in c) + "\n")
        for name, found in sides:
            f.write("sideset %s %d\n" % (name.replace(" ", "_"), len(found)))
            for e, s in found:
                f.write("%d %d\n" % (e, s))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("msh")
    ap.add_argument("exo")
    ap.add_argument("--mesher", default=os.path.join(os.path.dirname(__file__), "..", "build",
                                                     "drivers", "impm_mesh"))
    args = ap.parse_args()
    mesh = meshio.read(args.msh)
    blocks, sides = convert(mesh)
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as t:
        text = t.name
    try:
        write_text(text, mesh.points, blocks, sides)
        r = subprocess.run([args.mesher, "text", text, args.exo])
    finally:
        os.remove(text)
    sys.exit(r.returncode)


if __name__ == "__main__":
    main()
