#!/usr/bin/env python3
"""Runs doc/tutorial.md as a reader would, so that it cannot rot.

Every fenced block marked ```sh is run in order by bash -e in one scratch directory (the
reader's), with IMPM_HOME set to the source tree and the build's drivers first on PATH.
Blocks marked ```shell are shown only (they need Gmsh or ParaView's window).  A ```text block
right after a ```sh block is the output the text quotes: each of its lines must appear in
what the block printed, token by token, numbers to the digits quoted ("..." stands for any
tokens).  A block that fails, or a quoted line that does not appear, fails the test.

    tutorial.py --doc doc/tutorial.md --source . --drivers build/drivers [--keep DIR]
"""

import argparse
import decimal
import os
import re
import shutil
import subprocess
import sys
import tempfile

NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def blocks(text):
    """[(kind, body)] of the fenced blocks, in order."""
    return [(m.group(1), m.group(2)) for m in
            re.finditer(r"^```(\w*)\n(.*?)^```\s*$", text, re.M | re.S)]


def token_matches(quoted, printed):
    if quoted == printed:
        return True
    q, p = quoted.strip("(),;:"), printed.strip("(),;:")
    if NUMBER.match(q) and NUMBER.match(p):
        # Equal to the digits quoted: within half a unit of the last one.
        half = 0.5 * 10.0 ** decimal.Decimal(q).as_tuple().exponent
        return (abs(float(q) - float(p)) <= half * (1 + 1e-9) and
                quoted.replace(q, "") == printed.replace(p, ""))
    return False


def line_matches(quoted, printed):
    q, p = quoted.split(), printed.split()
    if "..." in q:  # a prefix and a suffix around any tokens
        k = q.index("...")
        head, tail = q[:k], q[k + 1:]
        return (len(p) >= len(head) + len(tail) and
                all(token_matches(a, b) for a, b in zip(head, p[:len(head)])) and
                all(token_matches(a, b) for a, b in zip(tail, p[len(p) - len(tail):])))
    return len(q) == len(p) and all(token_matches(a, b) for a, b in zip(q, p))


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--doc", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--drivers", required=True, help="the directory of impm and impm_mesh")
    p.add_argument("--keep", help="work here (kept) instead of a temporary directory")
    args = p.parse_args()
    with open(args.doc) as f:
        found = blocks(f.read())
    work = os.path.abspath(args.keep) if args.keep else tempfile.mkdtemp(prefix="impm-tutorial-")
    if args.keep:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
    env = dict(os.environ, IMPM_HOME=os.path.abspath(args.source),
               # impm first, then this python (Debian's, with meshio) as the reader's python3
               PATH=os.pathsep.join([os.path.abspath(args.drivers),
                                     os.path.dirname(sys.executable), os.environ["PATH"]]),
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    failures, printed, steps = [], None, 0
    for kind, body in found:
        if kind == "sh":
            steps += 1
            print("$ " + body.strip().replace("\n", "\n$ "), flush=True)
            r = subprocess.run(["bash", "-e", "-c", body], cwd=work, env=env,
                               capture_output=True, text=True)
            printed = (r.stdout + r.stderr).splitlines()
            print("\n".join(printed[-15:]))
            if r.returncode != 0:
                failures.append("block %d exits %d" % (steps, r.returncode))
                break
        elif kind == "text" and printed is not None:
            for quoted in body.splitlines():
                if quoted.strip() and not any(line_matches(quoted, l) for l in printed):
                    failures.append("block %d did not print: %s" % (steps, quoted.strip()))
            printed = None
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    print("tutorial: %d blocks run" % steps)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures or steps == 0 else 0)


if __name__ == "__main__":
    main()
