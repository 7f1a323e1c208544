#!/usr/bin/env python3
"""Checkpoints and restarts (impm --restart): a continued run must reach the uninterrupted
run's final state.

  split   runs a deck straight with checkpoints, and again in two parts: the second part
          restarts from a checkpoint of the first (--from-step N: the straight run's own
          checkpoint of step N; --stop SET: a first run stopped early by an override, then
          extended).  Same rank count: the final particle CSV and the history CSV must be
          identical text; another rank count (--np-restart): the particle columns within
          --rtol.
  crash   starts the deck with checkpoints and kills it (SIGKILL, the whole process group)
          --kills times, each at a random moment or, with --in-write, while a checkpoint
          after the first is being written (a .tmp file exists); after each kill the run
          restarts from the newest complete checkpoint.  The last run finishes; its particle and history CSV
          must be identical to the uninterrupted run's, and the Exodus files must hold the
          same time steps.
  stop    starts the deck without periodic checkpoints and sends it SIGTERM (or --signal INT
          or USR1; to mpirun on several ranks, which passes it on to every rank, SIGTERM and
          SIGINT about a second later) at a random moment after its first step.  The run must
          exit with status 5 (mpirun after SIGTERM or SIGINT: not 0), print one line that
          names the checkpoint it wrote and the command that continues from it, and leave
          Exodus files that netCDF reads; that command must then end the run with the particle
          and history CSV identical to the uninterrupted run's, and the same Exodus time steps.

  bad     checkpoints impm must refuse before writing anything, each with one line that
          names the file and the reason and exit status 1: a missing file, a truncated one,
          one with a changed value (its checksum), one of a newer format, a deck given as a
          checkpoint, and checkpoints of another problem (particle count, method,
          dimension: --other-deck, a deck of the other dimension).

Standard library only, and python3-netCDF4 for `bad`.
"""

import argparse
import csv
import glob
import os
import random
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time


def command(args, np, out, deck, sets, restart=None):
    cmd = []
    if np > 1:
        cmd += shlex.split(args.mpiexec) + [str(np)]
    cmd += [args.impm, "--output-dir", out]
    if restart:
        cmd += ["--restart", restart]
    for s in args.set + sets:
        cmd += ["--set", s]
    return cmd + [deck]


def run(args, np, out, sets, restart=None):
    cmd = command(args, np, out, args.deck, sets, restart)
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("impm failed: %s\n%s%s" % (" ".join(cmd), r.stdout[-3000:], r.stderr))
    return r


def stem(deck):
    return os.path.splitext(os.path.basename(deck))[0]


def text(out, deck, kind):
    with open(os.path.join(out, "%s_%s.csv" % (stem(deck), kind))) as f:
        return f.read()


def columns_agree(a, b, rtol):
    """Largest difference of the particle columns relative to each column's largest value
    (columns of round-off, all below 1e-9, compared absolutely)."""
    ra = list(csv.DictReader(a.splitlines()))
    rb = list(csv.DictReader(b.splitlines()))
    if len(ra) != len(rb):
        return float("inf"), "row count"
    worst, where = 0.0, ""
    for c in ra[0]:
        x = [float(r[c]) for r in ra]
        y = [float(r[c]) for r in rb]
        scale = max(abs(v) for v in x)
        diff = max(abs(p - q) for p, q in zip(x, y))
        rel = diff / scale if scale > 1e-9 else diff
        if rel > worst:
            worst, where = rel, c
    return worst, where


def checkpoint_sets(every):
    return ["Output/Checkpoint Every=%d" % every, "Output/Checkpoints Kept=0",
            "Solver/Print Iterations=false"]


def split(args):
    work = tempfile.mkdtemp(prefix="impm-restart-", dir=".")
    straight, parted = os.path.join(work, "straight"), os.path.join(work, "parted")
    every = args.from_step or args.every
    run(args, args.np, straight, checkpoint_sets(every))
    os.makedirs(parted)
    if args.from_step:
        # The straight run's outputs with its checkpoint of that step, as a run killed after
        # it would have left them: the restart keeps the history and Exodus steps before.
        name = "%s_checkpoint_%06d.nc" % (stem(args.deck), args.from_step)
        for f in os.listdir(straight):
            if "_checkpoint" not in f or f == name:
                shutil.copy(os.path.join(straight, f), parted)
        checkpoint = os.path.join(parted, name)
    else:
        run(args, args.np_write or args.np, parted, checkpoint_sets(every) + [args.stop])
        checkpoint = os.path.join(parted, "%s_checkpoint.nc" % stem(args.deck))
    r = run(args, args.np_restart or args.np, parted, checkpoint_sets(every), checkpoint)
    failures = []
    if "  step " not in r.stdout:
        failures.append("the restarted run took no step")
    a, b = text(straight, args.deck, "particles"), text(parted, args.deck, "particles")
    if args.rtol == 0:
        for kind in ("particles", "history"):
            same = text(straight, args.deck, kind) == text(parted, args.deck, kind)
            print("%s CSV: %s" % (kind, "identical" if same else "DIFFERENT"))
            if not same:
                failures.append("the %s CSV differs from the uninterrupted run's" % kind)
    else:
        worst, where = columns_agree(a, b, args.rtol)
        print("particle columns: largest relative difference %.3e (%s)" % (worst, where))
        if worst > args.rtol:
            failures.append("column %s differs by %.3e > %g" % (where, worst, args.rtol))
    shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def exodus_times(out, deck):
    """The time steps of each Exodus file, read with ncdump."""
    times = {}
    for path in sorted(glob.glob(os.path.join(out, stem(deck) + "_*.exo"))):
        dump = subprocess.run(["ncdump", "-v", "time_whole", path], capture_output=True,
                              text=True).stdout
        times[os.path.basename(path)] = dump[dump.rfind("time_whole ="):].strip()
    return times


def same_outputs(straight, continued, deck):
    """The problems with a continued run whose particle and history CSV must be the
    uninterrupted run's, bit for bit, and whose Exodus files must hold the same time steps."""
    problems = []
    for kind in ("particles", "history"):
        same = text(straight, deck, kind) == text(continued, deck, kind)
        print("%s CSV: %s" % (kind, "identical" if same else "DIFFERENT"))
        if not same:
            problems.append("the %s CSV differs from the uninterrupted run's" % kind)
    a, b = exodus_times(straight, deck), exodus_times(continued, deck)
    print("Exodus files: %s" % ("the same time steps" if a == b else "DIFFERENT time steps"))
    if a != b:
        problems.append("the Exodus files hold other time steps: %s against %s" % (b, a))
    return problems


def session_processes(sid):
    """The processes of session sid (mpirun puts its ranks in process groups of their own,
    but they stay in its session)."""
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[3]) == sid:  # fields after the command: state, ppid, pgrp, session
            pids.append(int(entry))
    return pids


def kill_session(p):
    """SIGKILL to every process of p's session, a crash of the whole run."""
    while True:
        pids = session_processes(p.pid)
        if not pids:
            break
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.01)
        p.poll()


def crash(args):
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="impm-crash-", dir=".")
    straight, crashed = os.path.join(work, "straight"), os.path.join(work, "crashed")
    sets = checkpoint_sets(args.every)
    sets[1] = "Output/Checkpoints Kept=2"
    began = time.time()
    run(args, args.np, straight, sets)
    wall = time.time() - began
    print("uninterrupted run: %.2f s" % wall)
    link = os.path.join(crashed, "%s_checkpoint.nc" % stem(args.deck))
    failures, kills, attempts = [], 0, 0
    restart, finished = None, False
    # With --in-write a kill counts when it landed in a write; one that came just after the
    # write's rename (the race between seeing the .tmp file and the signal) is not counted,
    # and the run restarts and is killed again, up to four times --kills attempts.
    while kills < args.kills and attempts < 4 * args.kills:
        attempts += 1
        cmd = command(args, args.np, crashed, args.deck, sets, restart)
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                             start_new_session=True)
        deadline = time.time() + rng.uniform(0.2, 0.9) * wall
        while p.poll() is None:
            # In a write that has a complete checkpoint before it, so that one must restart.
            writing = os.path.exists(link) and glob.glob(
                os.path.join(crashed, "*_checkpoint_*.nc.tmp"))
            if (args.in_write and writing) or (not args.in_write and time.time() > deadline):
                break
            time.sleep(0.0005 if args.in_write else 0.01)
        if p.poll() is not None:
            print("the run ended before kill %d" % (kills + 1))
            finished = p.returncode == 0
            if not finished:
                failures.append("the run before kill %d failed" % (kills + 1))
            break
        kill_session(p)
        p.wait()
        partial = glob.glob(os.path.join(crashed, "*_checkpoint_*.nc.tmp"))
        newest = os.path.realpath(link) if os.path.exists(link) else None
        if not args.in_write or partial:
            kills += 1
        print("kill %d at %s; restarting from %s" % (
            attempts, "a checkpoint write (%s)" % os.path.basename(partial[0]) if partial
            else ("just after a checkpoint write, not counted" if args.in_write
                  else "a random moment"),
            os.path.basename(newest) if newest else "the start"))
        restart = link if newest else None
    if args.in_write and kills < args.kills and not finished:
        failures.append("only %d of %d kills landed in a checkpoint write" % (kills, args.kills))
    if not finished:
        run(args, args.np, crashed, sets, restart)
    failures += same_outputs(straight, crashed, args.deck)
    if kills == 0:
        failures.append("no kill landed")
    shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def history_rows(out, deck):
    try:
        with open(os.path.join(out, stem(deck) + "_history.csv")) as f:
            return sum(1 for _ in f) - 1
    except OSError:
        return 0


def stop(args):
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="impm-stop-", dir=".")
    straight, stopped = os.path.join(work, "straight"), os.path.join(work, "stopped")
    sets = ["Solver/Print Iterations=false"]
    began = time.time()
    run(args, args.np, straight, sets)
    wall = time.time() - began
    print("uninterrupted run: %.2f s" % wall)
    number = {"TERM": signal.SIGTERM, "INT": signal.SIGINT, "USR1": signal.SIGUSR1}[args.signal]
    late = args.np > 1 and args.signal != "USR1"
    # mpirun passes SIGTERM and SIGINT on about a second after it got them.
    delay = max(0.0, 0.6 * wall - (1.2 if late else 0.0))
    failures = []
    for attempt in range(4):
        shutil.rmtree(stopped, ignore_errors=True)
        cmd = command(args, args.np, stopped, args.deck, sets)
        p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             start_new_session=True)
        while p.poll() is None and history_rows(stopped, args.deck) < 2:
            time.sleep(0.005)  # the initial state and the first step are written
        time.sleep(rng.uniform(0.0, delay) / 2 ** attempt)
        if p.poll() is None:
            os.kill(p.pid, number)
        out, err = p.communicate(timeout=600)
        if "impm: stopped by" in err or "impm: wrote" not in out:
            break
        print("the run ended before the signal reached it; again, earlier")
    else:
        sys.exit("FAIL: every run ended before its signal reached it")
    lines = [l for l in err.splitlines() if l.startswith("impm:")]
    print("exit status %d; %s" % (p.returncode, lines[-1] if lines else err.strip()[-500:]))
    expected = None if late else 5
    if (expected and p.returncode != expected) or p.returncode == 0:
        failures.append("exit status %d, not %s" % (p.returncode, expected or "non-zero"))
    received = "TERM" if late else args.signal  # mpirun ends a job with SIGTERM
    stop_lines = [l for l in lines if l.startswith("impm: stopped by SIG" + received)]
    if len(stop_lines) != 1 or "; continue with: " not in stop_lines[0]:
        sys.exit("FAIL: no single stop line:\n" + out[-2000:] + err)
    checkpoint = stop_lines[0].split(": checkpoint ", 1)[1].split(";", 1)[0]
    continued = shlex.split(stop_lines[0].split("; continue with: ", 1)[1])
    if not os.path.isfile(checkpoint):
        failures.append("the checkpoint %s is not there" % checkpoint)
    for path in sorted(glob.glob(os.path.join(stopped, "*.exo"))):
        if subprocess.run(["ncdump", "-h", path], capture_output=True).returncode != 0:
            failures.append("%s does not open" % os.path.basename(path))
    launcher = shlex.split(args.mpiexec) + [str(args.np)] if args.np > 1 else []
    r = subprocess.run(launcher + continued, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("FAIL: the continued run failed: %s\n%s%s" % (" ".join(continued),
                                                               r.stdout[-2000:], r.stderr))
    failures += same_outputs(straight, stopped, args.deck)
    shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def bad(args):
    import netCDF4  # Debian's python3-netCDF4: to edit checkpoints as a corruption would
    import numpy

    work = os.path.abspath(tempfile.mkdtemp(prefix="impm-bad-restart-", dir="."))
    source = os.path.join(work, "source")
    run(args, 1, source, checkpoint_sets(args.every))
    good = os.path.join(source, "%s_checkpoint_%06d.nc" % (stem(args.deck), args.every))

    def copy(name):
        path = os.path.join(work, name)
        shutil.copy(good, path)
        return path

    truncated = copy("truncated.nc")
    with open(truncated, "r+b") as f:
        f.truncate(os.path.getsize(good) // 2)
    changed = copy("changed.nc")
    with netCDF4.Dataset(changed, "a") as d:
        d["particle_x"][3, 0] = d["particle_x"][3, 0] + 1e-3
    newer = copy("newer.nc")
    with netCDF4.Dataset(newer, "a") as d:
        d.setncattr("impm_checkpoint_version", numpy.int32(99))
    more = os.path.join(work, "more")
    run(args, 1, more, checkpoint_sets(args.every) + ["Bodies/%s/Particles Per Cell=%d"
                                                       % (args.body, args.per_cell)])
    more = os.path.join(more, "%s_checkpoint_%06d.nc" % (stem(args.deck), args.every))
    other = os.path.join(work, "other")
    other_deck = args.other_deck
    r = subprocess.run(command(args, 1, other, other_deck, checkpoint_sets(1)), capture_output=True,
                       text=True)
    other = glob.glob(os.path.join(other, "*_checkpoint_*.nc"))
    if r.returncode != 0 or not other:
        sys.exit("the other deck did not write a checkpoint:\n" + r.stdout + r.stderr)
    # One bit flipped in each attribute's value (the step, the time, the steppers' and the
    # conditions' state, the run's identity): each has its checksum.
    flipped = []
    with netCDF4.Dataset(good) as d:
        names = [n for n in d.ncattrs()
                 if not n.endswith("_checksum") and n != "impm_checkpoint_version"]
    for k, name in enumerate(names):
        path = copy("flip%02d.nc" % k)
        with netCDF4.Dataset(path, "a") as d:
            value = d.getncattr(name)
            if isinstance(value, str):
                b = bytearray(value.encode())
                b[len(b) // 2] ^= 0x04
                d.setncattr(name, b.decode("latin-1"))
            else:
                a = numpy.array(value, ndmin=1).copy()
                a.view(numpy.uint8)[a.nbytes // 2] ^= 0x01
                d.setncattr(name, a)
        flipped.append((path, [], "attribute '%s' is corrupted" % name))
    # Not files: a loop of links reached the catch-all handler (exit 3, naming the deck), and
    # a FIFO would block open() for ever.
    loop, fifo, folder = (os.path.join(work, n) for n in ("loop.nc", "fifo.nc", "folder.nc"))
    os.symlink("loop_back.nc", loop)
    os.symlink("loop.nc", os.path.join(work, "loop_back.nc"))
    os.mkfifo(fifo)
    os.mkdir(folder)
    cases = flipped + [
        (os.path.join(work, "missing.nc"), [], "no such checkpoint file"),
        (loop, [], "is a loop of symbolic links"),
        (fifo, [], "is a FIFO, socket or device, not a regular file"),
        (folder, [], "is a directory, not a file"),
        (truncated, [], "is not a readable checkpoint"),
        (changed, [], "variable 'particle_x' is corrupted"),
        (newer, [], "has checkpoint format version 99; this impm reads format versions up to"),
        (args.deck, [], "is not a readable checkpoint"),
        (more, [], "its particle count is"),
        (good, ["Discretization/Method=" + args.other_method], "its method is"),
        # Other physics, refused with every change listed (it was continued silently).
        (good, ["Materials/column/E=2e6", "Time Integration/Load Steps=7"],
         "was written with other values of parameters that define the problem "
         "(Materials/column/E: 1e+06 -> 2e+06; Time Integration/Load Steps: "),
        (other[0], [], "its dimension is"),
    ]
    failures = []
    for checkpoint, sets, reason in cases:
        out = os.path.join(work, "out")
        r = subprocess.run(command(args, 1, out, args.deck, sets, checkpoint), capture_output=True,
                           text=True)
        lines = [l for l in r.stderr.splitlines() if l.startswith("impm:")]
        expected = "impm: error: %s: " % checkpoint
        ok = (r.returncode == 1 and len(lines) == 1 and lines[0].startswith(expected) and
              reason in lines[0] and not os.path.exists(out))
        print("%-4s %s" % ("ok" if ok else "FAIL", lines[0] if lines else r.stderr.strip()))
        if not ok:
            failures.append("%s (exit %d, %d lines, output %s): %s" % (
                os.path.basename(checkpoint), r.returncode, len(lines),
                "written" if os.path.exists(out) else "none", r.stderr.strip()[:300]))
        shutil.rmtree(out, ignore_errors=True)
    # ... and continued with --allow-physics-change, each change printed.
    out = os.path.join(work, "allowed")
    r = subprocess.run(command(args, 1, out, args.deck, ["Materials/column/E=2e6"], good)
                       + ["--allow-physics-change"], capture_output=True, text=True)
    note = "impm: note: the restart changes Materials/column/E: 1e+06 -> 2e+06"
    # ... and recorded in the history where the changed rows begin.
    histories = glob.glob(os.path.join(out, "*_history.csv"))
    recorded = histories and any(
        line.startswith("# restart at step ") and
        "changes Materials/column/E: 1e+06 -> 2e+06 (--allow-physics-change)" in line
        for line in open(histories[0]))
    ok = r.returncode == 0 and note in r.stdout and recorded
    print("%-4s %s" % ("ok" if ok else "FAIL", note if ok else r.stdout[-300:] + r.stderr))
    if not ok:
        failures.append("--allow-physics-change: exit %d, history note %s" %
                        (r.returncode, "written" if recorded else "missing"))
    shutil.rmtree(work)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def finished(args):
    """A restart with no step to take (from the last checkpoint of a finished run, or with a
    Final Time below the checkpoint's) says so, exits 0 and leaves the directory as it was:
    the history not cut back, no file claimed that it did not write."""
    work = os.path.abspath(tempfile.mkdtemp(prefix="impm-finished-", dir="."))
    out = os.path.join(work, "out")
    run(args, 1, out, checkpoint_sets(args.every))
    checkpoints = sorted(glob.glob(os.path.join(out, "%s_checkpoint_*.nc" % stem(args.deck))))
    history = os.path.join(out, stem(args.deck) + "_history.csv")
    particles = os.path.join(out, stem(args.deck) + "_particles.csv")
    with open(history) as f:
        before = f.read()
    os.remove(particles)  # so that a claim to have written it shows
    failures = []
    for sets in ([], ["Time Integration/Final Time=%s" % args.earlier]):
        r = subprocess.run(command(args, 1, out, args.deck, sets, checkpoints[-1]),
                           capture_output=True, text=True)
        with open(history) as f:
            after = f.read()
        said = r.stdout + r.stderr
        problems = []
        if r.returncode != 0:
            problems.append("exit %d" % r.returncode)
        if "no step to take, nothing written" not in said:
            problems.append("no word that there is nothing to do")
        if "impm: wrote" in said or os.path.exists(particles):
            problems.append("claims or writes files")
        if after != before:
            problems.append("the history changed")
        print("%-4s restart %s: %s" % ("FAIL" if problems else "ok", sets or "as written",
                                       ", ".join(problems) or said.strip().splitlines()[-1]))
        failures += problems
    shutil.rmtree(work)
    sys.exit(1 if failures else 0)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--mpiexec", default="mpiexec -n")
    sub = p.add_subparsers(dest="check", required=True)
    s = sub.add_parser("split")
    s.add_argument("--deck", required=True)
    s.add_argument("--np", type=int, default=1)
    s.add_argument("--np-write", type=int, help="ranks of the first part (default --np)")
    s.add_argument("--np-restart", type=int, help="ranks of the restart (default --np)")
    s.add_argument("--from-step", type=int, help="restart from the straight run's checkpoint")
    s.add_argument("--stop", help="the override that stops the first part early")
    s.add_argument("--every", type=int, default=10, help="Checkpoint Every with --stop")
    s.add_argument("--rtol", type=float, default=0.0, help="0: identical text")
    s.add_argument("--set", action="append", default=[])
    c = sub.add_parser("crash")
    c.add_argument("--deck", required=True)
    c.add_argument("--np", type=int, default=1)
    c.add_argument("--every", type=int, default=10)
    c.add_argument("--kills", type=int, default=1)
    c.add_argument("--in-write", action="store_true")
    c.add_argument("--seed", type=int, default=1)
    c.add_argument("--set", action="append", default=[])
    t = sub.add_parser("stop")
    t.add_argument("--deck", required=True)
    t.add_argument("--np", type=int, default=1)
    t.add_argument("--signal", choices=["TERM", "INT", "USR1"], default="TERM")
    t.add_argument("--seed", type=int, default=1)
    t.add_argument("--set", action="append", default=[])
    f = sub.add_parser("finished")
    f.add_argument("--deck", required=True)
    f.add_argument("--every", type=int, default=100)
    f.add_argument("--earlier", required=True, help="a Final Time before the run's end")
    f.add_argument("--set", action="append", default=[])
    b = sub.add_parser("bad")
    b.add_argument("--deck", required=True)
    b.add_argument("--every", type=int, default=2)
    b.add_argument("--body", required=True, help="a body of the deck (its particle count changes)")
    b.add_argument("--per-cell", type=int, default=3, help="its other Particles Per Cell")
    b.add_argument("--other-method", default="gimp")
    b.add_argument("--other-deck", required=True, help="a deck of the other dimension")
    b.add_argument("--set", action="append", default=[])
    args = p.parse_args()
    if args.check == "split" and not (args.from_step or args.stop):
        sys.exit("split needs --from-step or --stop")
    {"split": split, "crash": crash, "stop": stop, "bad": bad,
     "finished": finished}[args.check](args)


if __name__ == "__main__":
    main()
