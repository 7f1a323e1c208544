#!/usr/bin/env python3
"""Benchmark: AMPLE's Hencky column (input/column_hencky.xml: gimp, 40 load steps, 2 x 2
particles per cell) as the material-point count grows: wall time, peak memory, Newton
iterations per load step and the largest |u_y error| against the exact solution (that of
test/verification/column_hencky.py).  For reference, AMPLE-m under GNU Octave took 8.8 s,
35.5 s and 143 s at 64, 256 and 1024 material points on a machine like this one.

usage: hencky_column.py --impm build/drivers/impm [--points 64 256 ...] [--method gimp]
                        [--write doc/performance.md]
"""

import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time

from benchlib import ROOT, write_section

sys.path.insert(0, os.path.join(ROOT, "test", "verification"))
from column_hencky import exact_uy  # noqa: E402  (the exact solution, written once)

DECK = os.path.join(ROOT, "input", "column_hencky.xml")


def run(impm, points, method):
    out = tempfile.mkdtemp(prefix="impm-hencky-")
    cmd = ["/usr/bin/time", "-f", "%M", impm, "--output-dir", out]
    for s in ("Grid/Cells={1,%d}" % (points // 4), "Discretization/Method=" + method,
              "Output/Exodus=false", "Solver/Print Iterations=false"):
        cmd += ["--set", s]
    start = time.perf_counter()
    r = subprocess.run(cmd + [DECK], capture_output=True, text=True)
    wall = time.perf_counter() - start
    if r.returncode != 0:
        sys.exit("impm failed: %s\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    memory = int(r.stderr.strip().splitlines()[-1]) / 1024.0
    with open(os.path.join(out, "column_hencky_particles.csv")) as f:
        error = max(abs(float(p["u_y"]) - exact_uy(float(p["Y"]))) for p in csv.DictReader(f))
    with open(os.path.join(out, "column_hencky_history.csv")) as f:
        rows = list(csv.DictReader(f))[1:]
    shutil.rmtree(out)
    newton = sum(float(h["newton_iterations"]) for h in rows) / len(rows)
    return wall, memory, newton, error


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--points", type=int, nargs="+", default=[64, 256, 1024, 4096, 1000000])
    p.add_argument("--method", default="gimp")
    p.add_argument("--write", help="replace the hencky-column section of this file")
    args = p.parse_args()
    lines = ["| material points | wall [s] | peak memory [MB] | Newton iterations per step | "
             "max \\|u_y error\\| [m] |", "|---|---|---|---|---|"]
    for n in args.points:
        wall, memory, newton, error = run(args.impm, n, args.method)
        lines.append("| %d | %.2f | %.0f | %.2f | %.3e |" % (n, wall, memory, newton, error))
        print(lines[-1], flush=True)
    if args.write:
        write_section(args.write, "hencky-column", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
