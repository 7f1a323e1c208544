#!/usr/bin/env python3
"""Benchmark: the strongly compressed column on 1 and 2 ranks, the load balance's case.
AMPLE's Hencky column (input/column_hencky.xml: E = 10 kPa, gimp, 40 load steps) on 1 x N
cells compresses to about a third of its height, so a fixed split of the cells leaves every
particle on one rank from the 20th load step; the cells are repartitioned by their particles
(Load Balance).  Wall time (medians of alternating runs), the slowest rank's Newton solve and
repartition timers, the repartitions and the speed-up, with Repartition on and off, and with
the deck's banded LU exact across the ranks (its default) or block Jacobi.  Before and
after the runs, each core's speed on one small run (a 2-rank run goes at its slower core's
pace).

usage: compressed_column.py --impm build/drivers/impm [--cells 65536] [--repeat 3]
                            [--write doc/performance.md]
"""

import argparse
import re
import statistics

from benchlib import ROOT, cores_after_runs, cores_before_runs, run_impm, write_section
import os

DECK = os.path.join(ROOT, "input", "column_hencky.xml")


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--cells", type=int, default=65536)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--write", help="replace the compressed-column section of this file")
    args = p.parse_args()
    # (ranks, repartition, the banded LU across the ranks)
    cases = [(1, True, "exact"), (2, True, "exact"), (2, False, "exact"),
             (2, True, "block Jacobi")]
    runs = {c: [] for c in cases}
    cores_before = cores_before_runs(args.impm)
    for _ in range(args.repeat):  # alternating, so that the machine's drift hits every case
        for case in cases:
            np, balance, across = case
            sets = ["Grid/Cells={1,%d}" % args.cells,
                    "Load Balance/Repartition=%s" % ("true" if balance else "false"),
                    "Solver/Linear Solver/Preconditioner Types/Banded LU/Across Ranks=" + across]
            runs[case].append(run_impm(args.impm, DECK, sets, np=np))
            print("%d rank(s), repartition %s, %s: %.1f s" % (np, balance, across,
                                                              runs[case][-1].wall), flush=True)
    one = statistics.median(r.wall for r in runs[cases[0]])
    lines = ["| cells (particles) | ranks | repartition | banded LU across ranks | "
             "wall [s] (min-max) | speed-up | Newton solve [s] | repartition [s] | "
             "peak memory [MB] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for case in cases:
        np, balance, across = case
        rs = runs[case]
        wall = statistics.median(r.wall for r in rs)
        lines.append("| 1x%d (%d) | %d | %s | %s | %.1f (%.1f-%.1f) | %.2f | %.1f | %.2f | %.0f |" % (
            args.cells, 4 * args.cells, np, "on" if balance else "off",
            across if np > 1 else "-", wall,
            min(r.wall for r in rs), max(r.wall for r in rs), one / wall,
            statistics.median(r.timer("Newton solve") for r in rs),
            statistics.median(r.timer("repartition") for r in rs),
            statistics.median(r.memory for r in rs)))
        print(lines[-1], flush=True)
    lines += [""] + cores_after_runs(args.impm, cores_before)
    if args.write:
        write_section(args.write, "compressed-column", "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
