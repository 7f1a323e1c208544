#!/usr/bin/env python3
"""Benchmark: the NX x NY column on square cells (the P1 deck, input/column_self_weight.xml,
with linear-elastic E = 1 MPa, nu = 0, 2 x 2 particles per cell, 10 load steps, cpdi): the
linear solvers side by side on 1 and 2 ranks.  A grid NX x NY x NZ is the 3-D column
(input/column_self_weight_3d.xml, 2 x 2 x 2 particles per cell, rollers on the four sides).

The grid is NX cells wide and NY tall over the height 50, so the column is 50 NX / NY wide
(and 50 NZ / NY deep).
Configurations: impm's default for 2-D static steps (CG + MueLu smoothed aggregation
with preconditioner reuse), the same without reuse, the same with GMRES, Ifpack2 ILUT (the
1-D default), and additive Schwarz with a KLU2 LU per rank.  Records the wall time of the whole run
(median of --repeat runs, configurations alternating), the Newton solve time, Krylov
iterations per load step, peak memory (largest process) and per particle, and the RMS
displacement error against the deck's neo-Hookean exact solution (linear elasticity differs
from it by about 1e-2: the check is that every solver gives the same figure).  On several
rank counts, before and after the runs, each core's speed on one small run (a run on several
ranks goes at its slowest core's pace).

usage: column_grid.py --impm build/drivers/impm [--grids 32x256 64x512 10x125x10] [--repeat 3]
                      [--configs default ...] [--ranks 1 2] [--write doc/performance.md]
"""

import argparse
import os
import statistics

from benchlib import ROOT, cores_after_runs, cores_before_runs, run_impm, write_section

DECKS = {2: os.path.join(ROOT, "input", "column_self_weight.xml"),
         3: os.path.join(ROOT, "input", "column_self_weight_3d.xml")}
LS = "Solver/Linear Solver/"
CONFIGS = {
    "default": [LS + "Preconditioner Type=MueLu"],
    "MUMPS": [LS + "Linear Solver Type=MUMPS"],
    "default, no reuse": [LS + "Preconditioner Type=MueLu", "Solver/Preconditioner Reuse=off"],
    "default with GMRES": [LS + "Preconditioner Type=MueLu",
                           LS + "Linear Solver Types/Belos/Solver Type=Pseudo Block GMRES"],
    "ILUT": [LS + "Preconditioner Type=Ifpack2", LS + "Preconditioner Types/Ifpack2/Prec Type=ILUT"],
    # The P1 deck's own banded LU suits a column a few cells wide only; on these grids an
    # exact LU per rank is KLU2's (additive Schwarz).  The deck names its preconditioner
    # type, so each configuration names its own.
    "Schwarz KLU2": [LS + "Preconditioner Type=Ifpack2",
                     LS + "Preconditioner Types/Ifpack2/Prec Type=SCHWARZ",
                     LS + "Preconditioner Types/Ifpack2/Ifpack2 Settings/"
                     "schwarz: inner preconditioner name=AMESOS2"],
}


def column(cells):
    """The overrides for a grid of cells = (NX, NY) or (NX, NY, NZ) square cells."""
    lengths = ",".join(repr(50.0 * n / cells[1]) for n in cells)
    return ["Grid/Cells={%s}" % ",".join(str(n) for n in cells), "Grid/Length={%s}" % lengths,
            "Bodies/column/Upper Corner={%s}" % lengths, "Materials/column/Model=linear-elastic",
            "Time Integration/Load Steps=10", "Output/Every=1000"]


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--grids", nargs="+", default=["32x256", "64x512"])
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--configs", nargs="+", default=list(CONFIGS))
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    p.add_argument("--timeout", type=float, default=900.0)
    p.add_argument("--write")
    p.add_argument("--section", default="column-grid",
                   help="the section of --write the table replaces (column-3d for 3-D grids)")
    args = p.parse_args()
    lines = ["| grid (particles) | solver | ranks | wall [s] | Newton solve [s] | Krylov per step "
             "| Krylov per Newton | Newton solve per particle and Newton iteration [us] "
             "| memory [MB] | per particle [kB] | RMS error |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    several = max(args.ranks) > 1
    if several:
        cores_before = cores_before_runs(args.impm)
    for grid in args.grids:
        cells = [int(v) for v in grid.split("x")]
        particles = 2 ** len(cells)
        for n in cells:
            particles *= n
        cases = [(c, np) for c in args.configs for np in args.ranks]
        runs = {case: [] for case in cases}
        for _ in range(args.repeat):  # alternate the cases
            for case in cases:
                runs[case].append(run_impm(args.impm, DECKS[len(cells)], column(cells) + CONFIGS[case[0]],
                                           np=case[1], timeout=args.timeout))
        for (name, np), rs in runs.items():
            if None in rs:
                lines.append("| %s (%d) | %s | %d | stopped after %.0f s | | | | | | | |"
                             % (grid, particles, name, np, args.timeout))
                continue
            steps = [r for r in rs[0].history if int(float(r["step"])) > 0]
            krylov = sum(float(r["linear_iterations"]) for r in steps)
            newton = sum(float(r["newton_iterations"]) for r in steps)
            memory = max(r.memory for r in rs)
            solve = statistics.median(r.timer("Newton solve") for r in rs)
            lines.append("| %s (%d) | %s | %d | %.2f | %.2f | %.1f | %.1f | %.2f | %.0f | %.2f | %s |"
                         % (grid, particles, name, np, statistics.median(r.wall for r in rs),
                            solve, krylov / len(steps), krylov / newton,
                            solve / newton / particles * 1e6, memory,
                            memory * 1024.0 / particles * np, rs[0].rms))
            print(lines[-1], flush=True)
    if several:
        lines += [""] + cores_after_runs(args.impm, cores_before)
    if args.write:
        write_section(args.write, args.section, "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
