#!/usr/bin/env python3
"""Writes the CT-like image of input/porous_specimen.xml: a square specimen of W x W pixels,
an 8-bit grayscale PNG with scanner-like noise.  Matrix pixels have gray levels about 140,
stiff inclusions about 230, pores about 20 (empty: in no body's gray range); the pores and
inclusions are disks at random positions (seeded, so the image is reproducible).

    porous_image.py OUT.png [--pixels 48] [--seed 5]
"""

import argparse
import math
import random

from image_bodies import png


def specimen_rows(pixels, seed):
    rnd = random.Random(seed)
    features = []  # (x, y, radius, level), in pixels
    for level, count, rmin, rmax in ((20, 14, 1.5, 3.5), (230, 8, 1.5, 3.0)):
        while count:
            x, y = rnd.uniform(4, pixels - 4), rnd.uniform(4, pixels - 4)
            r = rnd.uniform(rmin, rmax)
            if all(math.hypot(x - a, y - b) > r + c + 1.0 for a, b, c, _ in features):
                features.append((x, y, r, level))
                count -= 1
    rows = []
    for row in range(pixels):
        line = []
        for col in range(pixels):
            level = 140
            for a, b, c, v in features:
                if math.hypot(col + 0.5 - a, row + 0.5 - b) <= c:
                    level = v
            line.append(max(0, min(255, int(round(level + rnd.gauss(0, 8))))))
        rows.append(line)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--pixels", type=int, default=48)
    ap.add_argument("--seed", type=int, default=5)
    args = ap.parse_args()
    png(args.out, specimen_rows(args.pixels, args.seed))


if __name__ == "__main__":
    main()
