#!/usr/bin/env python3
"""Benchmark: time per step of V1 (bar vibration) as the particle count grows, explicit
central difference against implicit Newmark, on a fixed grid (fem, total Lagrangian: one
system serves every step) and with moving particles (gimp, updated Lagrangian: map, graph
and transfers rebuilt every step).

Time per step = (wall(n2 steps) - wall(n1 steps)) / (n2 - n1), medians of --repeat runs,
which removes start-up and output.  The explicit time step is 0.9 h/c, Newmark's 5 h/c.
With --write, replaces the section between the markers in doc/performance.md.
"""

import argparse
import os
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "input", "bar_vibration.xml")
BEGIN, END = "<!-- dynamic-bar:begin -->", "<!-- dynamic-bar:end -->"
L, C = 25.0, 10.0


def wall(impm, particles, method, scheme, steps):
    cells = particles // 2
    h = L / cells
    dt = (0.9 if scheme == "explicit" else 5.0) * h / C
    out = tempfile.mkdtemp(prefix="impm-dyn-")
    # Four cells past the free end leave room for moving particles.
    sets = ["Grid/Cells={%d}" % (cells + 4), "Grid/Length={%r}" % (h * (cells + 4)),
            "Discretization/Method=" + method,
            "Time Integration/Type=" + scheme, "Time Integration/Time Step=%r" % dt,
            "Time Integration/Final Time=%r" % (steps * dt), "Output/Exodus=false",
            "Output/CSV=false", "Output/Every=100000", "Verification/Exact Displacement="]
    cmd = [impm, "--output-dir", out]
    for s in sets:
        cmd += ["--set", s]
    start = time.perf_counter()
    r = subprocess.run(cmd + [DECK], capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    if r.returncode != 0:
        raise SystemExit(r.stdout + r.stderr)
    return elapsed


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--particles", type=int, nargs="+", default=[1000, 10000, 100000])
    p.add_argument("--steps", type=int, nargs=2, default=[5, 25])
    p.add_argument("--write")
    args = p.parse_args()
    n1, n2 = args.steps
    lines = ["| particles | method | scheme | time per step [ms] |", "|---|---|---|---|"]
    for method in ("fem", "gimp"):
        for scheme in ("explicit", "newmark"):
            for n in args.particles:
                per = [(wall(args.impm, n, method, scheme, n2) - wall(args.impm, n, method, scheme, n1))
                       / (n2 - n1) for _ in range(args.repeat)]
                lines.append("| %d | %s | %s | %.2f |" % (n, method, scheme, 1e3 * statistics.median(per)))
                print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    if args.write:
        doc = open(args.write).read()
        start, end = doc.index(BEGIN) + len(BEGIN), doc.index(END)
        open(args.write, "w").write(doc[:start] + "\n" + text + doc[end:])


if __name__ == "__main__":
    main()
