#!/usr/bin/env python3
"""C1, two bars colliding on one grid with no contact code (PROBLEMS.md C1).

Runs the deck, then again up to the moment of largest compression, and checks against the
continuum answer (rho = A = 1, c = 10, v0 = 0.1, L = 1):
  - no particle of one bar ever passes a particle of the other (every step's history);
  - the plateau stress, the median particle stress at the largest compression, is within
    5% of -rho c v0 = -1;
  - contact (from the first change of the bars' velocities to their rebound) lasts 2L/c
    within one cell-crossing time h / (2 v0), the time the bars take to close one cell:
    MPM bodies interact as soon as they reach common grid nodes;
  - after separation the bars move at -v0 and +v0 (within --rebound-tol);
  - total momentum stays zero and total energy within --energy-tol of rho A L v0^2.
"""

import argparse
import shutil
import statistics
import sys

from impmrun import run_deck

V0, C, L, ENERGY = 0.1, 10.0, 1.0, 0.01


def run(args, sets, keep=False):
    out = run_deck(args.impm, args.deck, sets + args.set, "impm-c1-")
    history, particles = out.table("_history.csv"), out.table("_particles.csv")
    if keep and args.keep_history:
        shutil.copy(out.path("_history.csv"), args.keep_history)
    out.remove()
    return history, particles


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--cell", type=float, default=0.02, help="grid spacing h of the deck")
    p.add_argument("--energy-tol", type=float, default=0.02)
    p.add_argument("--rebound-tol", type=float, default=0.03)
    p.add_argument("--keep-history", help="copy the history CSV here (for the plot)")
    p.add_argument("--set", action="append", default=[])
    args = p.parse_args()

    history, _ = run(args, [], keep=True)
    t = [float(r["time"]) for r in history]
    v1 = [float(r["v_cm_left_bar"]) for r in history]
    v2 = [float(r["v_cm_right_bar"]) for r in history]
    gap = [float(r["x_min_right_bar"]) - float(r["x_max_left_bar"]) for r in history]
    energy = [float(r["total_energy"]) for r in history]
    momentum = [abs(float(r["momentum"])) for r in history]
    kinetic = [float(r["kinetic_energy"]) for r in history]
    failures = []

    print("smallest gap between the bars' particles: %.5f" % min(gap))
    if min(gap) <= 0:
        failures.append("a particle of one bar passed a particle of the other")

    onset = next(t[k] for k in range(len(t)) if v1[k] < 0.99 * V0)
    rebound = 0.95 * abs(v1[-1])
    end = next(t[k] for k in range(len(t)) if v1[k] < -rebound)
    duration, expected, window = end - onset, 2 * L / C, args.cell / (2 * V0)
    print("contact from t = %.4f to %.4f: %.4f (2L/c = %.4f, one cell-crossing time %.4f)"
          % (onset, end, duration, expected, window))
    if abs(duration - expected) > window:
        failures.append("contact lasted %.4f, not 2L/c = %.4f within %.4f" % (duration, expected, window))

    print("after separation: bars at %+.5f and %+.5f (v0 = %g)" % (v1[-1], v2[-1], V0))
    for name, v, target in (("left", v1[-1], -V0), ("right", v2[-1], V0)):
        if abs(v - target) > args.rebound_tol * V0:
            failures.append("the %s bar leaves at %+.5f, not %+.5f" % (name, v, target))

    drift = max(abs(e - ENERGY) for e in energy) / ENERGY
    print("total energy within %.2e of rho A L v0^2; largest |momentum| %.2e" % (drift, max(momentum)))
    if drift > args.energy_tol:
        failures.append("energy changed by %.2e, more than %.2e" % (drift, args.energy_tol))
    if max(momentum) > 1e-10:
        failures.append("total momentum %.2e is not zero" % max(momentum))

    squeezed = t[kinetic.index(min(kinetic))]
    _, particles = run(args, ["Time Integration/Final Time=%r" % squeezed])
    stress = [float(r["stress"]) for r in particles]
    plateau = statistics.median(stress)
    print("at the largest compression (t = %.4f): median stress %.4f (-rho c v0 = -1), "
          "extremes %.3f and %.3f at the contact interface" % (squeezed, plateau, min(stress),
                                                              max(stress)))
    if abs(plateau + 1.0) > 0.05:
        failures.append("plateau stress %.4f not within 5%% of -1" % plateau)

    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
