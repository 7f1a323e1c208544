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
import csv
import math
import os
import re
import shutil
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = os.path.join(ROOT, "input", "bar_static_s1.xml")
BEGIN, END = "<!-- static-bar:begin -->", "<!-- static-bar:end -->"

# GMRES with the two incomplete factorisations that handle the zero diagonal of the Robin
# rows (MueLu's relaxation smoothers divide by it; see doc/performance.md).
PRECONDITIONERS = {
    "ILUT": [],
    "RILUK(1)": ["Solver/Linear Solver/Preconditioner Types/Ifpack2/Prec Type=RILUK",
                 "Solver/Linear Solver/Preconditioner Types/Ifpack2/Ifpack2 Settings/"
                 "fact: iluk level-of-fill=1"],
}
SOLVE_PHASES = ("particle-grid map", "graph", "residual", "Jacobian", "Newton solve")


def run_once(impm, np, particles, preconditioner):
    out = tempfile.mkdtemp(prefix="impm-bench-")
    cmd = ["/usr/bin/time", "-f", "%e %M"]
    if np > 1:
        cmd += ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np)]
    cmd += [impm, "--output-dir", out]
    sets = ["Grid/Cells={%d}" % (particles // 2), "Discretization/Method=cpdi",
            "Output/Exodus=false", "Output/CSV=false", "Output/Timers=true",
            "Solver/Print Iterations=false", "Verification/Maximum RMS Error=0",
            "Verification/Reaction Tolerance=0"] + PRECONDITIONERS[preconditioner]
    for s in sets:
        cmd += ["--set", s]
    cmd.append(DECK)
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("impm failed:\n" + r.stdout + r.stderr)
    wall, rss = r.stderr.strip().splitlines()[-1].split()
    solve = 0.0
    for phase in SOLVE_PHASES:
        m = re.search(r"impm: %s\s+([0-9.eE+-]+)" % re.escape(phase), r.stdout)
        solve += float(m.group(1)) if m else 0.0
    history = list(csv.DictReader(open(os.path.join(out, "bar_static_s1_history.csv"))))
    shutil.rmtree(out)
    return (float(wall), solve, int(rss) / 1024.0, int(history[-1]["newton_iterations"]),
            int(history[-1]["linear_iterations"]))


def exponent(points):
    """Least-squares slope of log(time) against log(particles)."""
    if len(points) < 2:
        return float("nan")
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = statistics.mean(xs), statistics.mean(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


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
                wall = statistics.median(r[0] for r in runs)
                solve = statistics.median(r[1] for r in runs)
                rss = max(r[2] for r in runs)
                newton, belos = runs[0][3], runs[0][4]
                lines.append("| %d | %d | %s | %.2f | %.3f | %.0f | %d | %d |"
                             % (n, np, preconditioner, wall, solve, rss, newton, belos))
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
        doc = open(args.write).read()
        start, end = doc.index(BEGIN) + len(BEGIN), doc.index(END)
        open(args.write, "w").write(doc[:start] + "\n" + text + doc[end:])


if __name__ == "__main__":
    main()
