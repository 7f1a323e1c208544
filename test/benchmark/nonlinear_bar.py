#!/usr/bin/env python3
"""Benchmark: Newton-Krylov on N1 (nonlinear static bar, cubic law) as the particle count
grows, with the 1-D default (the banded LU) against Ifpack2's ILUT (the default before) and
MueLu as the preconditioner of GMRES.

For each particle count (2 per cell, cpdi, one load step) records the Newton iterations,
the Belos iterations summed over the Newton steps, the Newton solve time (Teuchos timer)
and the time per Newton iteration, the residual and Jacobian assembly times, the wall time
of the whole process and its peak memory: medians of --repeat runs.  Prints a Markdown
table and, with --write, replaces the section between the markers in doc/performance.md.

MueLu runs as unsmoothed aggregation with an RILUK smoother and a KLU2 coarse solve: the
Robin rows of eq. 1.18-1.19 have a zero diagonal, which the default smoothed aggregation
(prolongator damping by the inverse diagonal) and relaxation smoothers cannot take.
KLU2 works on one rank only (doc/performance.md), so MueLu runs on one rank.

usage: nonlinear_bar.py --impm build/drivers/impm [--repeat 3] [--write doc/performance.md]
"""

import argparse
import os

from benchlib import ROOT, exponent, median_run, run_impm, write_section

DECK = os.path.join(ROOT, "input", "bar_nonlinear_static.xml")

MUELU = "Solver/Linear Solver/Preconditioner Types/MueLu/"
PRECONDITIONERS = {
    "banded LU": [],
    "ILUT": ["Solver/Linear Solver/Preconditioner Type=Ifpack2"],
    "MueLu": ["Solver/Linear Solver/Preconditioner Type=MueLu",
              MUELU + "verbosity=none",
              MUELU + "multigrid algorithm=unsmoothed",
              MUELU + "smoother: type=RILUK",
              MUELU + "coarse: type=KLU2"],
}


def run_once(impm, particles, preconditioner, timeout):
    sets = ["Grid/Cells={%d}" % (particles // 2), "Discretization/Method=cpdi",
            "Verification/Exact Displacement=", "Verification/Expected F0=0",
            "Verification/Expected FL=0", "Verification/Reaction Tolerance=0"]
    return run_impm(impm, DECK, sets + PRECONDITIONERS[preconditioner], timeout=timeout)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--particles", type=int, nargs="+", default=[1000, 10000, 100000, 1000000])
    p.add_argument("--timeout", type=float, default=120.0,
                   help="stop a run after this many seconds and record it as stopped")
    p.add_argument("--write", help="Markdown file whose benchmark section is replaced")
    args = p.parse_args()

    lines = ["| particles | preconditioner | Newton | Belos | Newton solve [s] | per Newton "
             "iteration [ms] | residual [s] | Jacobian [s] | wall [s] | peak memory [MB] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    fits = []
    for preconditioner in PRECONDITIONERS:
        points = []
        for n in args.particles:
            runs = []
            for _ in range(args.repeat):
                runs.append(run_once(args.impm, n, preconditioner, args.timeout))
                if runs[-1] is None:
                    break
            if None in runs:
                lines.append("| %d | %s | stopped after %.0f s | | | | | | | |"
                             % (n, preconditioner, args.timeout))
                print(lines[-1], flush=True)
                break
            solve = median_run(runs, lambda r: r.timer("Newton solve"))
            last = runs[0].history[-1]
            newton = int(last["newton_iterations"])
            points.append((n, solve / newton))
            lines.append("| %d | %s | %d | %s | %.3f | %.2f | %.4f | %.4f | %.2f | %.0f |"
                         % (n, preconditioner, newton, last["linear_iterations"], solve,
                            1e3 * solve / newton, median_run(runs, lambda r: r.timer("residual")),
                            median_run(runs, lambda r: r.timer("Jacobian")),
                            median_run(runs, lambda r: r.wall), max(r.memory for r in runs)))
            print(lines[-1], flush=True)
        fits.append("- %s: time per Newton iteration grows like N^%.2f (%d to %d particles)"
                    % (preconditioner, exponent(points[1:]), args.particles[1], points[-1][0]))
    text = "\n".join(lines) + "\n\nScaling exponents (least-squares fit of log time against log N):\n\n"
    text += "\n".join(fits) + "\n"
    print(text)
    if args.write:
        write_section(args.write, "nonlinear-bar", text)


if __name__ == "__main__":
    main()
