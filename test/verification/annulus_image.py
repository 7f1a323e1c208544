#!/usr/bin/env python3
"""Rasterises the quarter annulus a <= r <= b, x, y >= 0 into a grayscale PNG of W x W pixels
covering [0, b] x [0, b]: a pixel is material (level 255) when its centre lies in the annulus,
else empty (0).  The image of input/cylinder_lame_image.xml and of the refinement study of
lame_cylinder.py.

    annulus_image.py OUT.png --pixels W [--radii a b]
"""

import argparse
import math

from image_bodies import png


def annulus_rows(pixels, a, b):
    size = b / pixels
    rows = []
    for row in range(pixels):  # row 0 at the top
        y = (pixels - 1 - row + 0.5) * size
        rows.append([255 if a <= math.hypot((c + 0.5) * size, y) <= b else 0
                     for c in range(pixels)])
    return rows


def write_annulus(path, pixels, a=1.0, b=2.0):
    """Writes the image; returns the number of material pixels."""
    rows = annulus_rows(pixels, a, b)
    png(path, rows)
    return sum(v > 0 for r in rows for v in r)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--pixels", type=int, required=True)
    ap.add_argument("--radii", type=float, nargs=2, default=[1.0, 2.0])
    args = ap.parse_args()
    n = write_annulus(args.out, args.pixels, *args.radii)
    print("%s: %d x %d pixels, %d material" % (args.out, args.pixels, args.pixels, n))


if __name__ == "__main__":
    main()
