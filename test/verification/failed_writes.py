#!/usr/bin/env python3
"""Outputs that cannot be written: impm must stop with one line "impm: error: <file>: <why>"
that names the file and the system's reason, a non-zero exit status, the files written before
complete and readable, no half-written file left, and the last complete checkpoint valid.

  limit FILE     a file size limit (ulimit -f, in KiB) at which FILE, an output of the colliding
                 disks, is the first that cannot be written: exodus (the domains file), history,
                 particles (the particle CSV, written with MPI-IO) or checkpoint.  For the
                 checkpoint the run restarts from an earlier checkpoint under the limit; the next
                 checkpoint fails, the earlier one stays, and a restart from it without the limit
                 ends as the uninterrupted run did (history CSV identical).
  readonly       the output directory exists but may not be written (as root: the run is
                 started as user nobody).
  vanished       the output directory is removed while the run writes into it.

Standard library only.  A run under a file size limit is started by mpirun (one rank): Open
MPI's own start-up of a run without mpirun writes files that the limit would stop.
"""

import argparse
import glob
import os
import pwd
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

DECK_SETS = {  # which outputs are on, so that FILE is the first to reach the limit
    "exodus": (200, ["Output/CSV=false"], "_domains.exo", "cannot write the Exodus file"),
    "history": (40, ["Output/Exodus=false", "Output/CSV=false"], "_history.csv", "cannot write"),
    "particles": (50, ["Output/Exodus=false", "Time Integration/Final Time=0.5"],
                  "_particles.csv", "cannot write"),
    "checkpoint": (120, ["Output/Exodus=false", "Output/CSV=false", "Output/Checkpoint Every=50",
                         "Output/Checkpoints Kept=0"],
                   "_checkpoint_000100.nc", "cannot write the checkpoint"),
}


def impm_command(args, out, sets, restart=None):
    cmd = [args.impm, "--quiet", "--output-dir", out]
    if restart:
        cmd += ["--restart", restart]
    for s in sets:
        cmd += ["--set", s]
    return cmd + [args.deck]


def limited(args, cmd, kib):
    """cmd under ulimit -f kib, as the only rank of an mpirun."""
    inner = "ulimit -f %d; exec %s" % (kib, " ".join(shlex.quote(c) for c in cmd))
    return shlex.split(args.mpiexec) + ["1", "sh", "-c", inner]


def impm_lines(r):
    return [l for l in r.stderr.splitlines() if l.startswith("impm:")]


def judge_failure(r, path, reason, out):
    """The problems with a run that had to fail writing `path`."""
    problems = []
    lines = impm_lines(r)
    print("exit status %d; %s" % (r.returncode, lines[-1] if lines else r.stderr.strip()[-300:]))
    if r.returncode == 0:
        problems.append("exit status 0")
    errors = [l for l in lines if l.startswith("impm: error:")]
    if len(errors) != 1:
        problems.append("%d error lines, not one" % len(errors))
    elif not errors[0].startswith("impm: error: " + path) or ": " + reason not in errors[0]:
        problems.append("the error does not name %s with '%s': %s" % (path, reason, errors[0]))
    elif not errors[0].endswith(")"):
        problems.append("the error gives no reason: " + errors[0])
    foreign = [l for l in (r.stdout + r.stderr).splitlines()
               if l.strip() and not l.startswith("impm:") and not l.startswith("  ")
               and not l.startswith("-" * 20) and "mpirun" not in l and "job" not in l
               and "Process name" not in l and "Exit code" not in l and "non-zero" not in l]
    if foreign:
        problems.append("lines that are not impm's: %r" % foreign[:3])
    problems += leftovers(out)
    return problems


def leftovers(out):
    """Half-written files, unreadable Exodus files, torn history rows."""
    problems = []
    if not os.path.isdir(out):
        return problems
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name)
        if name.endswith(".tmp") or name.endswith(".old"):
            problems.append("a half-written file remains: " + name)
        if name.endswith(".exo") or name.endswith(".nc"):
            if subprocess.run(["ncdump", "-h", path], capture_output=True).returncode != 0:
                problems.append(name + " does not open")
        if name.endswith("_history.csv"):
            with open(path) as f:
                rows = f.read().split("\n")
            if rows[-1] != "":
                problems.append("the history's last row is torn: %r" % rows[-1][:40])
            width = len(rows[0].split(","))
            if any(len(r.split(",")) != width for r in rows[1:-1]):
                problems.append("the history has rows of another length")
    return problems


def limit(args):
    kib, sets, suffix, reason = DECK_SETS[args.file]
    stem = os.path.splitext(os.path.basename(args.deck))[0]
    work = tempfile.mkdtemp(prefix="impm-write-", dir=".")
    out = os.path.abspath(os.path.join(work, "out"))
    restart = None
    sets = sets + ["Solver/Print Iterations=false"]
    if args.file == "checkpoint":
        straight = os.path.join(work, "straight")
        r = subprocess.run(impm_command(args, straight, sets), capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("the run without a limit failed:\n" + r.stdout + r.stderr)
        os.makedirs(out)
        for name in os.listdir(straight):  # its outputs as they stood after step 50
            if name.endswith("_history.csv") or name == "%s_checkpoint_000050.nc" % stem:
                shutil.copy(os.path.join(straight, name), out)
        restart = os.path.join(out, "%s_checkpoint_000050.nc" % stem)
    r = subprocess.run(limited(args, impm_command(args, out, sets, restart), kib),
                       capture_output=True, text=True)
    problems = judge_failure(r, os.path.join(out, stem + suffix) + ":", reason, out)
    if args.file == "checkpoint":
        if not os.path.exists(restart):
            problems.append("the earlier checkpoint is gone")
        r = subprocess.run(impm_command(args, out, sets, restart), capture_output=True, text=True)
        if r.returncode != 0:
            problems.append("the restart from the earlier checkpoint failed: " + r.stderr[-300:])
        else:
            with open(os.path.join(straight, stem + "_history.csv")) as a, \
                    open(os.path.join(out, stem + "_history.csv")) as b:
                same = a.read() == b.read()
            print("restarted from the earlier checkpoint: history CSV %s" %
                  ("identical" if same else "DIFFERENT"))
            if not same:
                problems.append("the restarted run's history differs from the uninterrupted run's")
    shutil.rmtree(work)
    finish(problems)


def readonly(args):
    work = os.path.abspath(tempfile.mkdtemp(prefix="impm-readonly-", dir="."))
    out = os.path.join(work, "out")
    os.makedirs(out)
    cmd = impm_command(args, out, [])
    if os.geteuid() == 0:  # root may write anywhere: run as nobody
        nobody = pwd.getpwnam("nobody")
        os.chmod(work, 0o755)
        os.chmod(out, 0o555)
        cmd = ["setpriv", "--reuid=%d" % nobody.pw_uid, "--regid=%d" % nobody.pw_gid,
               "--clear-groups"] + cmd
    else:
        os.chmod(out, 0o555)
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=work)
    problems = judge_failure(r, out + "/", "", out)
    lines = [l for l in impm_lines(r) if l.startswith("impm: error:")]
    if lines and not ("Permission denied" in lines[0] or "Read-only" in lines[0]):
        problems.append("the reason is not the permission: " + lines[0])
    if os.listdir(out):
        problems.append("files were written: %s" % os.listdir(out))
    os.chmod(out, 0o755)
    shutil.rmtree(work)
    finish(problems)


def readonly_file(args):
    """A new run in the directory of a finished one, one of whose files may not be written:
    refused naming that file, and every file of the finished run stays as it was (the Exodus
    files, the history and the CSVs; a run used to reset the first files before failing on
    the third)."""
    work = os.path.abspath(tempfile.mkdtemp(prefix="impm-readonly-file-", dir="."))
    out = os.path.join(work, "out")
    os.makedirs(out)
    cmd = impm_command(args, out, [])
    if os.geteuid() == 0:  # root may write anywhere: run as nobody, who owns the directory
        nobody = pwd.getpwnam("nobody")
        os.chmod(work, 0o755)
        os.chown(out, nobody.pw_uid, nobody.pw_gid)
        cmd = ["setpriv", "--reuid=%d" % nobody.pw_uid, "--regid=%d" % nobody.pw_gid,
               "--clear-groups"] + cmd
    first = subprocess.run(cmd, capture_output=True, text=True, cwd=work)
    problems = [] if first.returncode == 0 else ["the first run failed: " + first.stderr[-300:]]
    stem = os.path.splitext(os.path.basename(args.deck))[0]
    locked = os.path.join(out, stem + "_particles.exo")
    before = {}
    for name in sorted(os.listdir(out)):
        with open(os.path.join(out, name), "rb") as f:
            before[name] = f.read()
    os.chmod(locked, 0o444)
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=work)
    problems += judge_failure(r, locked, "cannot be written, so no output was changed "
                              "(Permission denied)", out)
    for name, data in before.items():
        with open(os.path.join(out, name), "rb") as f:
            if f.read() != data:
                problems.append("the second run changed " + name)
    os.chmod(locked, 0o644)
    shutil.rmtree(work)
    finish(problems)


def vanished(args):
    work = os.path.abspath(tempfile.mkdtemp(prefix="impm-vanished-", dir="."))
    out = os.path.join(work, "out")
    stem = os.path.splitext(os.path.basename(args.deck))[0]
    p = subprocess.Popen(impm_command(args, out, ["Solver/Print Iterations=false"]),
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    history = os.path.join(out, stem + "_history.csv")
    while p.poll() is None:
        try:
            with open(history) as f:
                if sum(1 for _ in f) > 20:
                    break
        except OSError:
            pass
        time.sleep(0.005)
    shutil.rmtree(out, ignore_errors=True)
    stdout, stderr = p.communicate(timeout=600)
    r = subprocess.CompletedProcess(p.args, p.returncode, stdout, stderr)
    problems = judge_failure(r, out + "/", "", out)
    lines = [l for l in impm_lines(r) if l.startswith("impm: error:")]
    if lines and "No such file or directory" not in lines[0]:
        problems.append("the reason is not the missing directory: " + lines[0])
    shutil.rmtree(work)
    finish(problems)


def finish(problems):
    for p in problems:
        print("FAIL:", p)
    sys.exit(1 if problems else 0)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--mpiexec", required=True, help="the launcher up to the process count")
    p.add_argument("--deck", required=True)
    sub = p.add_subparsers(dest="case", required=True)
    l = sub.add_parser("limit")
    l.add_argument("file", choices=sorted(DECK_SETS))
    sub.add_parser("readonly")
    sub.add_parser("vanished")
    sub.add_parser("readonly-file")
    args = p.parse_args()
    args.impm = os.path.abspath(args.impm)
    args.deck = os.path.abspath(args.deck)
    {"limit": limit, "readonly": readonly, "vanished": vanished,
     "readonly-file": readonly_file}[args.case](args)


if __name__ == "__main__":
    main()
