#!/usr/bin/env python3
"""Benchmark: P1 (the column under self-weight, 20 load steps, neo-Hookean) with cpdi as
the particle count grows: the deck's preconditioner (LAPACK's banded LU of each rank's rows,
impm's "Banded LU") against the same LU through Ifpack2's block relaxation (the deck's choice
before), additive Schwarz with a KLU2 LU of each rank's rows (the choice before that), Ifpack2
ILUT (impm's default) and MueLu, on 1 and 2 ranks.

The column's grid is one cell wide, {1, N} cells with 2 x 2 particles per cell, so N =
particles / 4; cells are 1 wide and 50 / N tall.  Records the wall time of the whole run,
Newton iterations and Belos iterations per load step (means over the 20 steps), the
Newton solve time (Teuchos timer), peak memory per particle, and the RMS displacement
error against the exact solution (a check that the fast run is also right).  MueLu:
smoothed aggregation with 2 equations per node and an RILUK smoother (point relaxation
fails on the stretched cells of fine columns: several hundred GMRES iterations), KLU2
coarse solve, so one rank only.  Medians of --repeat runs; a run longer than --timeout
seconds is stopped and recorded.

usage: column.py --impm build/drivers/impm [--repeat 1] [--preconditioners ILUT ...]
                 [--write doc/performance.md]
"""

import argparse
import os
import statistics

from benchlib import ROOT, run_impm, write_section

DECK = os.path.join(ROOT, "input", "column_self_weight.xml")
MUELU = "Solver/Linear Solver/Preconditioner Types/MueLu/"
IFPACK2 = "Solver/Linear Solver/Preconditioner Types/Ifpack2/"
USE_IFPACK2 = "Solver/Linear Solver/Preconditioner Type=Ifpack2"
ILUT = [USE_IFPACK2, IFPACK2 + "Prec Type=ILUT"]
SCHWARZ_KLU2 = [USE_IFPACK2, IFPACK2 + "Prec Type=SCHWARZ",
                IFPACK2 + "Ifpack2 Settings/schwarz: inner preconditioner name=AMESOS2"]
IFPACK2_BANDED = [USE_IFPACK2, IFPACK2 + "Prec Type=BLOCK_RELAXATION"] + [
    IFPACK2 + "Ifpack2 Settings/" + s for s in
    ["relaxation: container=Banded", "partitioner: type=linear", "partitioner: local parts=1",
     "relaxation: type=Jacobi"]]
CONFIGS = [
    ("banded LU", 1, []),
    ("banded LU", 2, []),
    ("Ifpack2 banded", 1, IFPACK2_BANDED),
    ("Ifpack2 banded", 2, IFPACK2_BANDED),
    ("Schwarz KLU2", 1, SCHWARZ_KLU2),
    ("Schwarz KLU2", 2, SCHWARZ_KLU2),
    ("ILUT", 1, ILUT),
    ("ILUT", 2, ILUT),
    ("MueLu", 1, ["Solver/Linear Solver/Preconditioner Type=MueLu", MUELU + "verbosity=none",
                  MUELU + "number of equations=2", MUELU + "smoother: type=RILUK",
                  MUELU + "coarse: type=KLU2"]),
]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--repeat", type=int, default=1)
    p.add_argument("--particles", type=int, nargs="+", default=[1000, 10000, 100000, 1000000])
    p.add_argument("--timeout", type=float, default=900.0)
    p.add_argument("--preconditioners", nargs="+", default=[c[0] for c in CONFIGS],
                   help="the configurations to run (names as in the table)")
    p.add_argument("--write")
    args = p.parse_args()
    lines = ["| particles | preconditioner | ranks | wall [s] | Newton solve [s] | Newton per step "
             "| Belos per step | Belos per Newton | memory per particle [kB] (largest process) | RMS error |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for name, np, sets in CONFIGS:
        if name not in args.preconditioners:
            continue
        for n in args.particles:
            base = ["Grid/Cells={1,%d}" % (n // 4), "Discretization/Method=cpdi",
                    "Output/Every=1000"]
            runs = []
            for _ in range(args.repeat):
                runs.append(run_impm(args.impm, DECK, base + sets, np=np, timeout=args.timeout))
                if runs[-1] is None:
                    break
            if None in runs:
                lines.append("| %d | %s | %d | stopped after %.0f s | | | | | | |"
                             % (n, name, np, args.timeout))
                print(lines[-1], flush=True)
                break
            steps = [r for r in runs[0].history if int(float(r["step"])) > 0]
            newton = sum(float(r["newton_iterations"]) for r in steps) / len(steps)
            belos = sum(float(r["linear_iterations"]) for r in steps) / len(steps)
            lines.append("| %d | %s | %d | %.1f | %.2f | %.1f | %.1f | %.1f | %.2f | %s |" % (
                n, name, np, statistics.median(r.wall for r in runs),
                statistics.median(r.timer("Newton solve") for r in runs), newton, belos,
                belos / newton, max(r.memory for r in runs) * 1024.0 / n, runs[0].rms))
            print(lines[-1], flush=True)
    text = "\n".join(lines) + "\n"
    if args.write:
        write_section(args.write, "column", text)


if __name__ == "__main__":
    main()
