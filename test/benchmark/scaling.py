#!/usr/bin/env python3
"""Benchmark: strong scaling of P1 (the column, 20 load steps) and P3 (the colliding disks,
a fixed number of Newmark steps) with cpdi on 1 and 2 ranks, with the time of each phase
from impm's Teuchos timers (the slowest rank's): set-up (which contains the first map and
graph), particle-grid map, graph, assembly
(residual + Jacobian), Newton solve (which contains the assembly NOX asks for and the
linear solves), particle update, migration and output (Exodus and CSV at the last step).

Each point is the median of --repeat runs, the 1-rank and 2-rank runs taken in turn (1, 2,
1, 2, ...) so that a drift of the machine's speed reaches both alike; the phase times are
medians too.  Speed-up = wall(1 rank) / wall(2 ranks); efficiency = speed-up / 2.  The
spread of the wall times (min-max over the repeats) is reported with them.  With --write,
replaces the section between the markers in doc/performance.md.

usage: scaling.py --impm build/drivers/impm [--repeat 3] [--write doc/performance.md]
"""

import argparse
import math
import os

from benchlib import ROOT, median_run, run_impm, write_section

PHASES = ["set-up", "particle-grid map", "graph", "residual", "Jacobian", "Newton solve",
          "particle update", "migration", "output"]


def column(particles):
    return (os.path.join(ROOT, "input", "column_self_weight.xml"),
            ["Grid/Cells={1,%d}" % (particles // 4)])


def disks(particles, steps=10):
    # The two disks hold about 0.2513 of the unit square: N^2 cells, 4 particles per cell.
    n = int(round(math.sqrt(particles / (4 * 0.2513))))
    dt = 0.1 / n  # 0.5 of the deck's 0.005 at 20 cells, scaled with h
    return (os.path.join(ROOT, "input", "colliding_disks.xml"),
            ["Grid/Cells={%d,%d}" % (n, n), "Time Integration/Time Step=%r" % dt,
             "Time Integration/Final Time=%r" % (steps * dt)])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--particles", type=int, nargs="+", default=[100000, 1000000])
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--write")
    args = p.parse_args()
    header = ("| problem | particles | ranks | wall [s] (min-max) | speed-up | efficiency | "
              + " | ".join(PHASES) + " |")
    lines = [header, "|" + "---|" * (6 + len(PHASES))]
    for name, setup in (("P1 column", column), ("P3 disks, 10 steps", disks)):
        for n in args.particles:
            deck, sets = setup(n)
            sets = sets + ["Output/Exodus=true", "Output/CSV=true", "Output/Every=100000"]
            runs = {1: [], 2: []}
            for _ in range(args.repeat):
                for np in (1, 2):
                    runs[np].append(run_impm(args.impm, deck, sets, np=np))
            base = median_run(runs[1], lambda r: r.wall)
            for np in (1, 2):
                wall = median_run(runs[np], lambda r: r.wall)
                spread = "%.1f (%.1f-%.1f)" % (wall, min(r.wall for r in runs[np]),
                                               max(r.wall for r in runs[np]))
                speedup = base / wall
                phases = [median_run(runs[np], lambda r, t=t: r.timer(t)) for t in PHASES]
                lines.append("| %s | %d | %d | %s | %.2f | %.2f | " % (name, n, np, spread, speedup,
                                                                       speedup / np)
                             + " | ".join("%.2f" % t for t in phases) + " |")
                print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    if args.write:
        write_section(args.write, "scaling", text)


if __name__ == "__main__":
    main()
