#!/usr/bin/env python3
"""Benchmark: assemble and solve S1 with cpdi as the particle count grows.

For each particle count (2 per cell), rank count and preconditioner, runs impm several times
and records the median wall time of the whole process, the median time of the solve phases
(map, graph, residual, Jacobian, Newton solve: the Teuchos timers), the peak memory of the
largest process, and the Newton and Belos iteration counts.  Prints a Markdown table and,
with --write, replaces the section between the markers in doc/performance.md.

usage: static_bar.py --impm build/drivers/impm [--repeat 3] [--write doc/performance.md]
"""

import argparse
import os

from benchlib import ROOT, exponent, median_run, run_impm, write_section

DECK = os.path.join(ROOT, "input", "bar_static_s1.xml")

# GMRES with the 1-D default (the banded LU, whose row exchanges handle the zero diagonal of
# the Robin rows) and the two incomplete factorisations that handle it too (MueLu's
# relaxation smoothers divide by it; see doc/performance.md).
PRECONDITIONERS = {
    "banded LU": [],
    "ILUT": ["Solver/Linear Solver/Preconditioner Type=Ifpack2"],
    "RILUK(1)": ["Solver/Linear Solver/Preconditioner Type=Ifpack2",
                 "Solver/Linear Solver/Preconditioner Types/Ifpack2/Prec Type=RILUK",
                 "Solver/Linear Solver/Preconditioner Types/Ifpack2/Ifpack2 Settings/"
                 "fact: iluk level-of-fill=1"],
}
SOLVE_PHASES = ("particle-grid map", "graph", "residual", "Jacobian", "Newton solve")


def run_once(impm, np, particles, preconditioner):
    sets = ["Grid/Cells={%d}" % (particles // 2), "Discretization/Method=cpdi",
            "Verification/Maximum RMS Error=0", "Verification/Reaction Tolerance=0"]
    return run_impm(impm, DECK, sets + PRECONDITIONERS[preconditioner], np)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--particles", type=int, nargs="+", default=[1000, 10000, 100000, 1000000])
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    p.add_argument("--write", help="Markdown file whose benchmark section is replaced")
    args = p.parse_args()

    lines = ["| particles | ranks | preconditioner | wall [s] | solve phases [s] | peak memory [MB] "
             "| Newton | Belos |", "|---|---|---|---|---|---|---|---|"]
    fits = []
    for preconditioner in PRECONDITIONERS:
        for np in args.ranks:
            walls, solves = [], []
            for n in args.particles:
                runs = [run_once(args.impm, np, n, preconditioner) for _ in range(args.repeat)]
                wall = median_run(runs, lambda r: r.wall)
                solve = median_run(runs, lambda r: sum(r.timer(t) for t in SOLVE_PHASES))
                last = runs[0].history[-1]
                lines.append("| %d | %d | %s | %.2f | %.3f | %.0f | %s | %s |"
                             % (n, np, preconditioner, wall, solve, max(r.memory for r in runs),
                                last["newton_iterations"], last["linear_iterations"]))
                print(lines[-1], flush=True)
                walls.append((n, wall))
                solves.append((n, solve))
            large = [pt for pt in solves if pt[0] >= 10000]
            fits.append("- %s, %d rank%s: solve phases grow like N^%.2f (10^4 to 10^6), whole "
                        "process like N^%.2f (10^3 to 10^6)"
                        % (preconditioner, np, "s" if np > 1 else "", exponent(large),
                           exponent(walls)))
            print(fits[-1], flush=True)
    text = "\n".join(lines) + "\n\nScaling exponents (least-squares fit of log time against log N):\n\n" + \
        "\n".join(fits) + "\n"
    if args.write:
        write_section(args.write, "static-bar", text)


if __name__ == "__main__":
    main()
