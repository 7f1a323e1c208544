#!/usr/bin/env python3
"""AMPLE's Hencky column against its exact solution (doc/verification/plasticity.md).

Runs input/column_hencky.xml at Grid/Cells = {1, N} for each N and measures the largest
|u_y error| over the particles against the exact large-deformation solution
  u_y(Y) = (1/c) [w0 + w0^2/2 - a0 - (w + w^2/2 - a)],  a = c (H - Y),  w = W(a),
with c = rho0 g / E and W Lambert's function (Newton's method here).  Asserts that the error
converges and, with --bound, that it is no larger than the given figures (AMPLE's on the
same grids).  Standard library only.
"""

import argparse
import math
import sys

from impmrun import run_deck

H, E, RHO, G = 50.0, 1.0e4, 80.0, 10.0
C = RHO * G / E


def lambert_w(a):
    """The principal branch of W at a >= 0: w e^w = a."""
    w = math.log1p(a)
    for _ in range(50):
        step = (w * math.exp(w) - a) / (math.exp(w) * (w + 1))
        w -= step
        if abs(step) < 1e-16 * max(1.0, abs(w)):
            break
    return w


def exact_uy(Y):
    a, a0 = C * (H - Y), C * H
    w, w0 = lambert_w(a), lambert_w(a0)
    return ((w0 + w0 * w0 / 2 - a0) - (w + w * w / 2 - a)) / C


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--cells", type=int, nargs="+", default=[16, 64, 256])
    p.add_argument("--bound", type=float, nargs="+", help="largest max |u_y error| at each N")
    p.add_argument("--set", action="append", default=[])
    args = p.parse_args()

    print("exact: base stretch %.6f, top displacement %.4f"
          % (lambert_w(C * H) / (C * H), exact_uy(H)))
    errors, failures = [], []
    for k, n in enumerate(args.cells):
        out = run_deck(args.impm, args.deck, ["Grid/Cells={1,%d}" % n,
                                              "Solver/Print Iterations=false"] + args.set,
                       "impm-hencky-")
        rows = out.table("_particles.csv")
        out.remove()
        error = max(abs(float(r["u_y"]) - exact_uy(float(r["Y"]))) for r in rows)
        errors.append(error)
        rate = math.log(errors[-2] / error) / math.log(n / args.cells[k - 1]) if k else float("nan")
        print("N = %4d (%5d material points): max |u_y error| = %.4e m, rate %.2f"
              % (n, len(rows), error, rate))
        if args.bound and error > args.bound[k]:
            failures.append("max |u_y error| %.4e at N = %d is above %g" % (error, n, args.bound[k]))
        if k and not error < errors[-2]:
            failures.append("the error does not decrease from N = %d to %d" % (args.cells[k - 1], n))
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
