#!/usr/bin/env python3
"""Benchmark: making particles from geometry files on one rank (geometry_build): a
4096 x 4096 8-bit PNG whose material is a disk of a third of its area (5.6 million
particles), and a 1000 x 1000-element QUAD4 mesh (10^6 particles with tracked corners).
Reports the median over --repeat runs of the time to read the file and create the cpdi
particles, and the growth of the peak memory over that time per particle.  Targets: under
10 s and under 1 kB per particle.

usage: geometry.py --impm build/drivers/impm [--repeat 3] [--write doc/performance.md]
"""

import argparse
import math
import os
import statistics
import subprocess
import sys
import tempfile

from benchlib import ROOT, write_section

sys.path.insert(0, os.path.join(ROOT, "test", "verification"))
from image_bodies import write_png  # noqa: E402

PIXELS = 4096


def disk_png(path, pixels):
    """The disk of radius sqrt(pixels^2 / (3 pi)) at the centre: level 255 inside, 0 outside."""
    radius = math.sqrt(pixels * pixels / (3 * math.pi))
    c = pixels / 2
    raw = bytearray()
    for row in range(pixels):
        y = row + 0.5 - c
        half = math.sqrt(max(0.0, radius * radius - y * y))
        lo = max(0, min(pixels, int(math.ceil(c - half - 0.5))))
        hi = max(lo, min(pixels, int(math.floor(c + half - 0.5)) + 1))
        raw += b"\0" + b"\0" * lo + b"\xff" * (hi - lo) + b"\0" * (pixels - hi)
    write_png(path, pixels, pixels, bytes(raw))


def measure(cmd, repeat):
    runs = []
    for _ in range(repeat):
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.split()
        values = dict(zip(out[0::2], out[1::2]))
        runs.append((int(values["particles"]), float(values["seconds"]),
                     float(values["peak_kB_per_particle"])))
    return (runs[0][0], statistics.median(r[1] for r in runs),
            statistics.median(r[2] for r in runs))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True, help="build/drivers/impm: the build tree is found from it")
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--write", help="replace the geometry-build section of this file")
    args = p.parse_args()
    build = os.path.dirname(os.path.dirname(os.path.abspath(args.impm)))
    bench = os.path.join(build, "test", "benchmark", "geometry_build")
    mesher = os.path.join(build, "drivers", "impm_mesh")
    work = tempfile.mkdtemp(prefix="impm-geometry-")
    image, mesh = os.path.join(work, "disk.png"), os.path.join(work, "square.exo")
    disk_png(image, PIXELS)
    subprocess.run([mesher, "rectangle", mesh, "--box", "0", "1", "0", "1", "--cells", "1000",
                    "1000", "--distort", "0.2"], check=True, capture_output=True)
    rows = [("image, 4096 x 4096 PNG, 8 pixels per cell",
             measure([bench, "image", image, repr(1.0 / PIXELS), "128", "255", "1.0", "512"],
                     args.repeat)),
            ("mesh, 1000 x 1000 QUAD4 (Exodus), 2 elements per cell",
             measure([bench, "mesh", mesh, "1.0", "500"], args.repeat))]
    for f in (image, mesh):
        os.remove(f)
    os.rmdir(work)
    lines = ["| geometry | particles | time [s] | peak memory per particle [kB] |",
             "|---|---|---|---|"]
    for name, (n, seconds, kb) in rows:
        lines.append("| %s | %d | %.2f | %.3f |" % (name, n, seconds, kb))
    text = "\n".join(lines) + "\n"
    print(text)
    if args.write:
        write_section(args.write, "geometry-build", text)


if __name__ == "__main__":
    main()
