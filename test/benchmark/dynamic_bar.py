#!/usr/bin/env python3
"""Benchmark: time per step of V1 (bar vibration) as the particle count grows, explicit
central difference against implicit Newmark, on a fixed grid (fem, total Lagrangian: one
system serves every step) and with moving particles (gimp, updated Lagrangian: map, graph
and transfers rebuilt every step).

Time per step = (wall(n2 steps) - wall(n1 steps)) / (n2 - n1), medians of --repeat runs,
which removes start-up and output; n1 = 5 and n2 = 5 + max(20, 2e6 / particles) (explicit:
max(400, 2e6 / particles), its steps being ten times cheaper), so that the timed steps
outweigh the jitter of process start-up (tens of ms).  The explicit time
step is 0.5 h/c (gimp's moving particles are stable only below about 0.65 h/c, see
doc/theory.md), Newmark's 5 h/c.  For the explicit rows the last column gives the time per
step in residual evaluations: one evaluation is what a Newton iteration pays for the
residual, the laws' stress update plus the force sums (the `stress update` and `residual`
timers of the n2-step run, per call; with gimp a step also updates the stress at its
start), so that the target "an explicit step costs at most 2
residual evaluations" is read off one command.
--history-every N writes the history every N steps (Output/History Every): the steps between
its rows skip the energies.  --schemes, --methods: a part of the table.
With --write, replaces the section between the markers in doc/performance.md.
"""

import argparse
import math
import os
import statistics

from benchlib import ROOT, run_impm, write_section

DECK = os.path.join(ROOT, "input", "bar_vibration.xml")
L, C = 25.0, 10.0


def run(impm, particles, method, scheme, steps, history_every=1):
    cells = particles // 2
    h = L / cells
    dt = (0.5 if scheme == "explicit" else 5.0) * h / C
    # Room past the free end for its motion (amplitude about 0.1 in V1) on any grid.
    pad = 4 + int(math.ceil(0.5 / h))
    sets = ["Grid/Cells={%d}" % (cells + pad), "Grid/Length={%r}" % (h * (cells + pad)),
            "Discretization/Method=" + method,
            "Time Integration/Type=" + scheme, "Time Integration/Time Step=%r" % dt,
            "Time Integration/Final Time=%r" % (steps * dt), "Output/Every=100000",
            "Verification/Exact Displacement=", "Verification/Maximum RMS Error=0",
            "Output/History Every=%d" % history_every]
    return run_impm(impm, DECK, sets, history=False)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--particles", type=int, nargs="+", default=[1000, 10000, 100000])
    p.add_argument("--history-every", type=int, default=1)
    p.add_argument("--methods", nargs="+", default=["fem", "gimp"])
    p.add_argument("--schemes", nargs="+", default=["explicit", "newmark"])
    p.add_argument("--write")
    args = p.parse_args()
    lines = ["| particles | method | scheme | time per step [ms] | residual evaluations per step |",
             "|---|---|---|---|---|"]
    for method in args.methods:
        for scheme in args.schemes:
            for n in args.particles:
                n1 = 5
                n2 = n1 + max(400 if scheme == "explicit" else 20, 2000000 // n)
                per, ratio = [], []
                for _ in range(args.repeat):
                    long = run(args.impm, n, method, scheme, n2, args.history_every)
                    short = run(args.impm, n, method, scheme, n1, args.history_every)
                    step = (long.wall - short.wall) / (n2 - n1)
                    evaluation = long.per_call("residual") + long.per_call("stress update")
                    per.append(step)
                    ratio.append(step / evaluation)
                cost = "%.1f" % statistics.median(ratio) if scheme == "explicit" else "-"
                lines.append("| %d | %s | %s | %.2f | %s |" % (n, method, scheme,
                                                               1e3 * statistics.median(per), cost))
                print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    if args.write:
        write_section(args.write, "dynamic-bar", text)


if __name__ == "__main__":
    main()
