"""Single-rank runs started side by side (no launcher) must not disturb each other.

impm starts a one-rank run as an isolated Open MPI singleton with a session directory of its
own (drivers/impm.cpp); runs that shared one broke each other's MPI-IO files.  This runs a
deck once, then --runs copies of it at once, --trials times, and requires every output file
(particle CSV written through MPI-IO, Exodus files, checkpoints) to equal the lone run's
byte for byte, no run to fail or print an Open MPI complaint, and no session directory to
be left behind.

usage: side_by_side.py --impm IMPM --deck DECK [--set P=V]... [--runs 4] [--trials 2]
"""

import argparse
import filecmp
import glob
import os
import subprocess
import sys
import tempfile


def start(impm, deck, sets, out):
    cmd = [impm, "--output-dir", out]
    for s in sets:
        cmd += ["--set", s]
    return subprocess.Popen(cmd + [deck], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)


def finish(proc):
    """The run's pid; exits when it failed or Open MPI complained (mca_... messages)."""
    text, _ = proc.communicate()
    if proc.returncode != 0 or "mca_" in text:
        sys.exit("impm failed or Open MPI complained (status %d):\n%s" % (proc.returncode, text))
    return proc.pid


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--impm", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--set", action="append", default=[])
    p.add_argument("--runs", type=int, default=4)
    p.add_argument("--trials", type=int, default=2)
    args = p.parse_args()
    env_set = [v for v in ("OMPI_MCA_ess_singleton_isolated", "OMPI_MCA_orte_tmpdir_base")
               if v in os.environ]
    if env_set:
        sys.exit("unset %s: the test is of impm's own choice" % " ".join(env_set))
    work = tempfile.mkdtemp(prefix="side-by-side-", dir=".")
    reference = os.path.join(work, "alone")
    pids = [finish(start(args.impm, args.deck, args.set, reference))]
    files = sorted(os.listdir(reference))
    if not files:
        sys.exit("the lone run wrote nothing")
    failures = []
    for trial in range(args.trials):
        outs = [os.path.join(work, "t%d-r%d" % (trial, r)) for r in range(args.runs)]
        procs = [start(args.impm, args.deck, args.set, out) for out in outs]
        pids += [finish(proc) for proc in procs]
        for out in outs:
            _, mismatch, missing = filecmp.cmpfiles(reference, out, files, shallow=False)
            failures += ["%s/%s differs from the lone run's" % (out, f) for f in mismatch]
            failures += ["%s/%s is missing or unreadable" % (out, f) for f in missing]
    temp = os.environ.get("TMPDIR", "/tmp")
    left = [d for pid in pids for d in glob.glob(os.path.join(temp, "impm-singleton-%d" % pid))]
    failures += ["session directory left behind: %s" % d for d in left]
    print("%d runs in %d trials of %d at once; %d files compared per run"
          % (args.runs * args.trials, args.trials, args.runs, len(files)))
    if failures:
        sys.exit("\n".join(failures))
    subprocess.run(["rm", "-rf", work], check=True)
    print("all outputs equal the lone run's; no session directory left")


if __name__ == "__main__":
    main()
