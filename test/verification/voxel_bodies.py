#!/usr/bin/env python3
"""Bodies from voxel stacks (Shape = image in a 3-D deck): orientation in all three
directions, the slice order, two gray ranges, particles per voxel, PNG slices by a file
pattern and a multi-page 16-bit TIFF, and the refusals (doc/verification/geometry.md).

Writes its own stacks with image_bodies.py's PNG and TIFF writers:

- an asymmetric stack: the L of image_bodies.py in slices 0 and 1, one pixel at its top
  left in slice 2; pixels 0.25, slices 0.5 thick, origin (1, 1, 0.5): the particles must sit
  where the slices show the L, slice 0 lowest (Slice Order = bottom to top) or highest (top
  to bottom);
- the same stack as a multi-page 16-bit TIFF, the L at level 1000 and the pixel at 40000,
  read by two bodies: each particle's body follows its voxel's level;
- Particles Per Pixel = 2: 8 particles per voxel whose domains tile it, volumes summing to
  the voxels' exactly;
- a pattern without its Slices, a slice of another size, a missing slice, a TIFF page that
  is not there, a 2-entry origin and a range with no voxel: each a one-line `impm: error:`
  naming the parameter or the file and the reason, and no output.
"""

import argparse
import os
import tempfile

from image_bodies import (L_SHAPE, deck, expect_error, finish, image_body, particles, png,
                          tiff16_pages)

H, T = 0.25, 0.5  # pixel size, slice thickness
DOT = [["#" if (r, c) == (0, 0) else "." for c in range(6)] for r in range(5)]
STACK = [L_SHAPE, L_SHAPE, ["".join(row) for row in DOT]]  # slice 0 first


def voxel_body(file, lo, hi, slices=None, order="bottom to top", per_voxel=1,
               origin="{1.0, 1.0, 0.5}"):
    body = image_body(file, lo, hi, per_voxel, origin, H)
    body["Slice Thickness"] = ("double", T)
    body["Slice Order"] = ("string", order)
    if slices:
        body["Slices"] = ("Array(int)", "{%d, %d}" % slices)
    return body


def expected(order, which=None):
    """The particle centres the stack's selected voxels hold (which: a slice subset)."""
    out = []
    for k, rows in enumerate(STACK):
        if which is not None and k not in which:
            continue
        layer = k if order == "bottom to top" else len(STACK) - 1 - k
        for r, row in enumerate(rows):
            for c, ch in enumerate(row):
                if ch == "#":
                    out.append((round(1 + (c + 0.5) * H, 9), round(1 + (4 - r + 0.5) * H, 9),
                                round(0.5 + (layer + 0.5) * T, 9)))
    return sorted(out)


def centres(rows):
    return sorted((round(float(q["X"]), 9), round(float(q["Y"]), 9), round(float(q["Z"]), 9))
                  for q in rows)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    args = p.parse_args()
    work = tempfile.mkdtemp(prefix="impm-voxels-", dir=".")
    failures = []
    cells = (8, 8, 8)
    for k, rows in enumerate(STACK):
        png(os.path.join(work, "s%02d.png" % k), [[200 if ch == "#" else 0 for ch in row]
                                                  for row in rows])

    # Orientation: x along a row, y up the image, z up the stack (or down it).
    for order in ("bottom to top", "top to bottom"):
        path = os.path.join(work, "stack.xml")
        deck(path, {"b": voxel_body("s%02d.png", 100, 255, (0, 2), order)}, cells)
        got = centres(particles(args.impm, path))
        ok = got == expected(order)
        print("%s: %d particles, %s" % (order, len(got), "right way up" if ok else "WRONG"))
        if not ok:
            failures.append("%s: the particles are not where the slices show them: %s"
                            % (order, got))

    # Two materials in a multi-page 16-bit TIFF: the L at 1000, the dot at 40000.
    levels = [[[40000 if ch == "#" and k == 2 else 1000 if ch == "#" else 0 for ch in row]
               for row in rows] for k, rows in enumerate(STACK)]
    tiff16_pages(os.path.join(work, "stack.tif"), levels)
    path = os.path.join(work, "two.xml")
    deck(path, {"soft": voxel_body("stack.tif", 500, 1500),
                "hard": voxel_body("stack.tif", 30000, 50000)}, cells)
    rows = particles(args.impm, path)
    soft = centres(q for q in rows if float(q["body"]) == 0)
    hard = centres(q for q in rows if float(q["body"]) == 1)
    ok = soft == expected("bottom to top", {0, 1}) and hard == expected("bottom to top", {2})
    print("TIFF pages, two materials: %d and %d particles, %s"
          % (len(soft), len(hard), "each in its body" if ok else "WRONG"))
    if not ok:
        failures.append("multi-page TIFF with two ranges: soft %s, hard %s" % (soft, hard))

    # Particles Per Pixel = 2: 8 per voxel, domains tiling each voxel.
    path = os.path.join(work, "ppv.xml")
    deck(path, {"b": voxel_body("s%02d.png", 100, 255, (0, 2), per_voxel=2)}, cells)
    rows = particles(args.impm, path)
    voxels = len(expected("bottom to top"))
    volume = sum(float(q["volume"]) for q in rows)
    tiles = all(abs(float(q["r1_x"]) - H / 4) < 1e-14 and abs(float(q["r2_y"]) - H / 4) < 1e-14
                and abs(float(q["r3_z"]) - T / 4) < 1e-14 for q in rows)
    print("2 per voxel: %d particles for %d voxels, volume %.15g (voxels %.15g), domains %s"
          % (len(rows), voxels, volume, voxels * H * H * T, "tile them" if tiles else "WRONG"))
    if len(rows) != 8 * voxels or abs(volume - voxels * H * H * T) > 1e-14 or not tiles:
        failures.append("Particles Per Pixel = 2 does not tile the voxels")

    # Refusals.
    png(os.path.join(work, "s03.png"), [[200] * 4] * 4)  # another size
    bad = {
        "noslices": ({"b": voxel_body("s%02d.png", 100, 255)},
                     ["Bodies/b/Slices", "is a pattern", "first and last slice"]),
        "size": ({"b": voxel_body("s%02d.png", 100, 255, (0, 3))},
                 ["s03.png", "is 4 x 4 pixels; the first slice is 6 x 5"]),
        "missing": ({"b": voxel_body("s%02d.png", 100, 255, (5, 6))},
                    ["s05.png", "the image file does not exist"]),
        "page": ({"b": voxel_body("stack.tif", 500, 1500, (0, 3))},
                 ["stack.tif", "has no page 3 (it has 3, counted from 0)"]),
        "origin": ({"b": voxel_body("stack.tif", 500, 1500, origin="{1.0, 1.0}")},
                   ["Bodies/b/Image Origin", "expected 3 entries (x, y, z) for a voxel stack"]),
        "empty": ({"b": voxel_body("stack.tif", 2000, 3000)},
                  ["Bodies/b/Gray Range", "no voxel", "stack.tif"]),
        "pattern": ({"b": voxel_body("s%02d_%s.png", 100, 255, (0, 2))},
                    ["Bodies/b/Image File", "one integer conversion"]),
    }
    for name, (bodies, words) in bad.items():
        path = os.path.join(work, name + ".xml")
        deck(path, bodies, cells)
        expect_error(args.impm, path, words, failures)

    finish(work, failures)


if __name__ == "__main__":
    main()
