"""Shared pieces of the benchmarks: run impm once and collect what it reports, fit scaling
exponents, and replace a marked section of doc/performance.md."""

import csv
import math
import os
import re
import shutil
import statistics
import subprocess
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class Run:
    """One impm process: wall time [s], peak memory of the largest process [MB], the Teuchos
    timers by name [s] and the rows of the history CSV."""

    def __init__(self, wall, memory, timers, history, rms=None, calls=None):
        self.wall, self.memory, self.timers, self.history = wall, memory, timers, history
        self.rms = rms  # the RMS displacement error impm reported, as printed
        self.calls = calls or {}  # each timer's call count (several ranks: the minimum's)

    def timer(self, name):
        return self.timers.get(name, 0.0)

    def per_call(self, name):
        """A timer's mean time per call [s] (0 when it never ran)."""
        return self.timer(name) / self.calls[name] if self.calls.get(name) else 0.0


def run_impm(impm, deck, sets, np=1, history=True, timeout=None):
    """Runs impm on deck with the --set overrides (output files off except the history CSV,
    timers on); raises SystemExit with impm's output when it fails.  Returns None when
    the run takes longer than timeout seconds (and stops it)."""
    out = tempfile.mkdtemp(prefix="impm-bench-")
    cmd = ["/usr/bin/time", "-f", "%e %M"]  # elapsed, peak resident memory [KB]
    if np > 1:
        cmd += ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np)]
    cmd += [impm, "--output-dir", out]
    # The history CSV is always written; the particle table and Exodus files are not.
    base = ["Output/Exodus=false", "Output/CSV=false", "Output/Timers=true",
            "Solver/Print Iterations=false"]
    for s in base + list(sets):
        cmd += ["--set", s]
    cmd.append(deck)
    start = time.perf_counter()  # /usr/bin/time's %e has a resolution of 10 ms
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        shutil.rmtree(out, ignore_errors=True)
        return None
    wall = time.perf_counter() - start
    if r.returncode != 0:
        shutil.rmtree(out, ignore_errors=True)
        raise SystemExit("impm failed: %s\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    rss = r.stderr.strip().splitlines()[-1].split()[1]
    timers, calls = {}, {}
    for m in re.finditer(r"^impm: ([A-Za-z -]+?)\s+([0-9.eE+-]+ \(.*)$", r.stdout, re.M):
        # One rank: "time (calls)"; several: min, mean, max over ranks, then the mean over
        # call counts.  The slowest rank's time is the one that counts.
        values = re.findall(r"([0-9.eE+-]+) \(([0-9.eE+-]+)\)", m.group(2))
        timers[m.group(1)] = float(values[2][0] if len(values) >= 3 else values[0][0])
        calls[m.group(1)] = float(values[0][1])
    rows = []
    if history:
        name = os.path.splitext(os.path.basename(deck))[0] + "_history.csv"
        rows = list(csv.DictReader(open(os.path.join(out, name))))
    shutil.rmtree(out)
    rms = re.search(r"RMS displacement error (\S+)", r.stdout)
    return Run(wall, int(rss) / 1024.0, timers, rows, rms.group(1) if rms else None, calls)


def core_speeds(impm, repeat=2):
    """The wall time [s] of one small run (the Hencky column at 1 x 4096 cells, one rank)
    pinned to each core this process may use, the fastest of `repeat` on each.  On a shared
    machine the cores' speeds can differ for hours, and a run on several ranks goes at its
    slowest rank's pace: a speed-up over ranks measured then says more of the cores than of
    impm."""
    deck = os.path.join(ROOT, "input", "column_hencky.xml")
    out = tempfile.mkdtemp(prefix="impm-bench-")
    cmd = [impm, "--output-dir", out, "--set", "Grid/Cells={1,4096}", "--set",
           "Output/Exodus=false", "--set", "Output/CSV=false", deck]
    times = {}
    for core in sorted(os.sched_getaffinity(0)):
        best = float("inf")
        for _ in range(repeat):
            start = time.perf_counter()
            subprocess.run(cmd, capture_output=True, check=True,
                           preexec_fn=lambda c=core: os.sched_setaffinity(0, {c}))
            best = min(best, time.perf_counter() - start)
        times[core] = best
    shutil.rmtree(out)
    return times


def core_speeds_line(times):
    """One line for a benchmark's report: each core's time and the slowest over the fastest."""
    each = ", ".join("core %d %.2f s" % (c, t) for c, t in sorted(times.items()))
    return ("each core's time on the Hencky column at 1 x 4096 cells (one rank pinned to it, "
            "the fastest of 2): %s; slowest over fastest %.2f." % (each, max(times.values()) /
                                                                    min(times.values())))


def cores_before_runs(impm):
    """Times each core (core_speeds), prints the line and returns the times for
    cores_after_runs."""
    times = core_speeds(impm)
    print("Before the runs, " + core_speeds_line(times), flush=True)
    return times


def cores_after_runs(impm, before):
    """Times each core again and returns (and prints) the report's two lines: the cores
    before the runs and after them."""
    lines = ["Before the runs, " + core_speeds_line(before),
             "after them, " + core_speeds_line(core_speeds(impm))]
    print("\n".join(lines), flush=True)
    return lines


def median_run(runs, key):
    return statistics.median(key(r) for r in runs)


def exponent(points):
    """Least-squares slope of log(time) against log(N) for points (N, time)."""
    if len(points) < 2:
        return float("nan")
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = statistics.mean(xs), statistics.mean(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def write_section(path, name, text):
    """Replaces the text between <!-- name:begin --> and <!-- name:end --> in path."""
    begin, end = "<!-- %s:begin -->" % name, "<!-- %s:end -->" % name
    doc = open(path).read()
    start, stop = doc.index(begin) + len(begin), doc.index(end)
    open(path, "w").write(doc[:start] + "\n" + text + doc[stop:])
