#!/usr/bin/env python3
"""The strip footing's limit pressure against Prandtl's (doc/verification/plasticity.md).

Runs a footing deck (input/strip_footing.xml, input/strip_footing_dp.xml) at Grid/Cells =
{N, N} for each N and reads the footing's pressure q = -reaction_footing / B from the
history at every load step.  The limit pressure is q at the last step, where the curve has
reached its plateau: asserted by the rise over the last quarter of the settlement being
below --plateau of q.  Asserts that the error against --exact decreases under refinement and
is within --tolerance at the finest grid; with --newton-per-step, that every grid's load steps
take at most that many Newton iterations on average and none is cut back.  With --plot PNG it
also draws the load-settlement curves (needs matplotlib; the test itself uses the standard
library only).
"""

import argparse
import sys
import xml.etree.ElementTree as ElementTree

from impmrun import run_deck


def footing_settlement(deck):
    """The footing's final vertical displacement (Boundary Conditions/footing/Value)."""
    root = ElementTree.parse(deck).getroot()
    for bc in root.iter("ParameterList"):
        if bc.get("name") == "footing":
            for p in bc.iter("Parameter"):
                if p.get("name") == "Value":
                    return -float(p.get("value"))
    sys.exit("%s: no Boundary Conditions/footing/Value" % deck)


def plot(curves, exact, png, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    for n, (s, q) in curves.items():
        ax.plot(s, q, marker=".", label="%d x %d cells" % (n, n))
    ax.axhline(exact, color="k", linestyle="--", label="Prandtl %.4g" % exact)
    ax.set_xlabel("settlement / B")
    ax.set_ylabel("footing pressure q = reaction / B")
    ax.set_title(title)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--cells", type=int, nargs="+", default=[10, 20, 40])
    p.add_argument("--width", type=float, default=1.0, help="the footing's half-width B")
    p.add_argument("--exact", type=float, required=True, help="Prandtl's limit pressure")
    p.add_argument("--tolerance", type=float, default=0.0,
                   help="largest relative error of the limit pressure at the finest grid")
    p.add_argument("--plateau", type=float, default=0.01,
                   help="largest relative rise of q over the last quarter of the settlement")
    p.add_argument("--locks", type=float,
                   help="assert instead that the error stays above this at every grid (a "
                        "discretisation that locks), and nothing else")
    p.add_argument("--newton-per-step", type=float,
                   help="largest mean Newton iterations per load step; no step may be cut back")
    p.add_argument("--plot", help="write the load-settlement curves to this PNG")
    p.add_argument("--set", action="append", default=[])
    args = p.parse_args()

    settlement = footing_settlement(args.deck)
    errors, failures, curves = [], [], {}
    for k, n in enumerate(args.cells):
        out = run_deck(args.impm, args.deck, ["Grid/Cells={%d,%d}" % (n, n),
                                              "Solver/Print Iterations=false"] + args.set,
                       "impm-footing-")
        history = out.table("_history.csv")
        out.remove()
        s = [float(h["load_factor"]) * settlement / args.width for h in history]
        q = [-float(h["reaction_footing"]) / args.width for h in history]
        curves[n] = (s, q)
        quarter = next(i for i, si in enumerate(s) if si >= 0.75 * s[-1])
        rise = (q[-1] - q[quarter]) / q[-1]
        error = (q[-1] - args.exact) / args.exact
        errors.append(abs(error))
        steps = [h for h in history if int(float(h["step"])) > 0]
        newton = sum(int(h["newton_iterations"]) for h in steps)
        cut = sum(int(float(h["attempts"])) - 1 for h in steps)
        print("N = %3d: limit pressure %.5g, error %+.2f%% against %.5g; rise over the last "
              "quarter %.2f%%; %d Newton iterations in %d load steps (%.2f a step), %d cut-backs"
              % (n, q[-1], 100 * error, args.exact, 100 * rise, newton, len(steps),
                 newton / len(steps), cut))
        if args.newton_per_step and not newton / len(steps) <= args.newton_per_step:
            failures.append("%.2f Newton iterations per load step at N = %d, above %g"
                            % (newton / len(steps), n, args.newton_per_step))
        if args.newton_per_step and cut:
            failures.append("%d load steps cut back at N = %d" % (cut, n))
        if args.locks is not None:
            if not error > args.locks:
                failures.append("error %+.2f%% at N = %d: expected locking, above %+.2f%%"
                                % (100 * error, n, 100 * args.locks))
            continue
        if not abs(rise) < args.plateau:
            failures.append("no plateau at N = %d: q rises by %.2f%% over the last quarter"
                            % (n, 100 * rise))
        if k and not errors[-1] < errors[-2]:
            failures.append("the error does not decrease from N = %d to %d" % (args.cells[k - 1], n))
    if args.locks is None and not errors[-1] <= args.tolerance:
        failures.append("error %.2f%% at N = %d is above %.2f%%"
                        % (100 * errors[-1], args.cells[-1], 100 * args.tolerance))
    if args.plot:
        plot(curves, args.exact, args.plot, args.deck.rsplit("/", 1)[-1])
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
