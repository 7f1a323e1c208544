#!/usr/bin/env python3
"""Benchmark: the strip footing (input/strip_footing.xml: j2, 20 load steps) as the particle
count grows, on one and two ranks, with impm's default linear solver (MUMPS's LU): one
particle per cell, and 2 x 2 particles per cell with F-bar (the density of the other decks,
which locks without it).  Wall time, the Newton solve's time, Newton iterations per load
step, linear iterations per Newton iteration (1 for a direct solve), peak memory per particle
of the largest process, and the limit pressure's error against Prandtl's.  A run longer than
--timeout seconds is stopped and recorded as such, and larger grids at that density and rank
count are not tried.

usage: strip_footing.py --impm build/drivers/impm [--particles 1e4 ...] [--ranks 1 2]
                        [--density 1 2] [--timeout 3600] [--write doc/performance.md]
"""

import argparse
import math
import os

from benchlib import ROOT, run_impm, write_section

DECK = os.path.join(ROOT, "input", "strip_footing.xml")
PRANDTL = 2 + math.pi  # c_u = 1, B = 1


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--particles", type=float, nargs="+", default=[1e4, 1e5, 1e6])
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    p.add_argument("--density", type=int, nargs="+", default=[1, 2],
                   help="particles per cell and direction (above 1: with F-bar)")
    p.add_argument("--timeout", type=float, default=3600.0)
    p.add_argument("--write", help="replace the strip-footing section of this file")
    args = p.parse_args()
    lines = ["| particles | per cell | ranks | wall [s] | Newton solve [s] | Newton per step | "
             "linear per Newton | memory per particle [kB] | limit pressure error |",
             "|---|---|---|---|---|---|---|---|---|"]
    for density in args.density:
        for np in args.ranks:
            footing(args, density, np, lines)
    if args.write:
        write_section(args.write, "strip-footing", "\n".join(lines) + "\n")


def footing(args, density, np, lines):
    """The runs at one density on np ranks, up the particle counts, until one is stopped."""
    for particles in args.particles:
        n = int(round(math.sqrt(particles) / density))
        sets = ["Grid/Cells={%d,%d}" % (n, n), "Bodies/soil/Particles Per Cell=%d" % density,
                "Discretization/F-bar=%s" % ("cell" if density > 1 else "none")]
        run = run_impm(args.impm, DECK, sets, np=np, timeout=args.timeout)
        count = (n * density) ** 2
        if run is None:
            lines.append("| %d | %d x %d | %d | stopped after %.0f s | | | | | |"
                         % (count, density, density, np, args.timeout))
            print(lines[-1], flush=True)
            return
        steps = [h for h in run.history if int(float(h["step"])) > 0]
        newton = sum(float(h["newton_iterations"]) for h in steps)
        linear = sum(float(h["linear_iterations"]) for h in steps)
        q = -float(steps[-1]["reaction_footing"])
        lines.append("| %d | %d x %d | %d | %.1f | %.1f | %.1f | %.1f | %.2f | %+.2f%% |" % (
            count, density, density, np, run.wall, run.timer("Newton solve"),
            newton / len(steps), linear / newton, run.memory * 1024.0 / count,
            100 * (q - PRANDTL) / PRANDTL))
        print(lines[-1], flush=True)


if __name__ == "__main__":
    main()
