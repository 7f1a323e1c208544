#!/usr/bin/env python3
"""V1, axial vibration of a fixed-free bar: checks a run against the discrete theory.

The first mode sin(k x_i) is an exact eigenvector of the fixed-free FEM system with uniform
cells, with frequency (PROBLEMS.md V1)
    lumped      w_h = (2c/h) sin(kh/2),
    consistent  w_h = (c/h) sqrt(6 (1 - cos kh) / (2 + cos kh)).
A time integrator turns it at w_bar:
    Newmark average acceleration   w_bar dt = 2 atan(w_h dt / 2)   (energy exactly conserved)
    central difference             w_bar dt = 2 asin(w_h dt / 2)
    primer eq. 1.53 as printed     unstable: the mode's amplitude grows by
                                   |lambda| = sqrt(1 + (w_h dt)^2 / 2) per step.
Checks (each optional): the period measured from the zero crossings of the centre-of-mass
velocity against 2 pi / w_bar; the energy drift; the particle u and v at the end against
the discrete solution (nodal values (v0/w_h) sin(w_bar t) sin(k x_i), v0 cos(w_bar t) sin(k x_i),
interpolated with phi_ip) and against the exact continuum solution within the error this
theory predicts; the growth rate of the primer update.
"""

import argparse
import math
import sys

from impmrun import run_deck

E, RHO, L, V0 = 100.0, 1.0, 25.0, 0.1
C = math.sqrt(E / RHO)
K = math.pi / (2 * L)
W = K * C


def run(args, sets):
    out = run_deck(args.impm, args.deck, sets, "impm-v1-")
    history, particles = out.table("_history.csv"), out.table("_particles.csv")
    out.remove()
    return history, particles


def discrete_frequency(mass, h):
    if mass == "lumped":
        return 2 * C / h * math.sin(K * h / 2)
    return C / h * math.sqrt(6 * (1 - math.cos(K * h)) / (2 + math.cos(K * h)))


def tent_weights(x, h, n):
    """Node indices and tent values at x (the fem particles are Gauss points: phi = N_i)."""
    i = min(int(x / h), n - 1)
    s = x / h - i
    return [(i, 1 - s), (i + 1, s)]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--scheme", choices=["newmark", "central", "primer"], required=True)
    p.add_argument("--mass", choices=["lumped", "consistent"], default="lumped")
    p.add_argument("--cells", type=int, default=16)
    p.add_argument("--dt", type=float, required=True)
    p.add_argument("--final-time", type=float, required=True)
    p.add_argument("--period-tol", type=float, help="relative tolerance on the period")
    p.add_argument("--energy-drift", type=float, help="largest relative energy change")
    p.add_argument("--discrete-tol", type=float, help="particle u, v against the discrete solution")
    p.add_argument("--exact", action="store_true", help="particle u, v against the exact solution")
    p.add_argument("--growth-tol", type=float, help="primer: relative error of the growth rate")
    p.add_argument("--set", action="append", default=[])
    args = p.parse_args()

    h = L / args.cells
    wh = discrete_frequency(args.mass, h)
    Omega = wh * args.dt
    if args.scheme == "newmark":
        wbar = 2 * math.atan(Omega / 2) / args.dt
    else:  # central difference (the primer update is only checked for its growth)
        wbar = 2 * math.asin(Omega / 2) / args.dt
    sets = ["Grid/Cells={%d}" % args.cells, "Time Integration/Time Step=%r" % args.dt,
            "Time Integration/Final Time=%r" % args.final_time] + args.set
    if args.scheme == "newmark":
        sets.append("Time Integration/Mass=" + args.mass)
    history, particles = run(args, sets)
    rows = history[1:]
    failures = []
    print("w = %.10f, w_h = %.10f (%s mass), w_bar = %.10f" % (W, wh, args.mass, wbar))

    if args.period_tol:
        t = [float(r["time"]) for r in rows]
        v = [float(r["v_cm_bar"]) for r in rows]
        crossings = [t[k] - v[k] * (t[k + 1] - t[k]) / (v[k + 1] - v[k])
                     for k in range(len(v) - 1) if v[k] * v[k + 1] < 0]
        period = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)
        predicted = 2 * math.pi / wbar
        error = abs(period - predicted) / predicted
        print("period: measured %.10f, predicted %.10f, relative difference %.2e (%d crossings)"
              % (period, predicted, error, len(crossings)))
        if error > args.period_tol:
            failures.append("period differs from the prediction by %.2e" % error)

    if args.energy_drift is not None:
        energy = [float(r["total_energy"]) for r in rows]
        drift = max(abs(e - energy[0]) for e in energy) / energy[0]
        print("energy: %.15g at the first step, largest relative change %.2e over %d steps"
              % (energy[0], drift, len(energy)))
        if drift > args.energy_drift:
            failures.append("energy drift %.2e above %.2e" % (drift, args.energy_drift))

    if args.growth_tol:
        energy = [float(r["total_energy"]) for r in history]
        n = len(energy) - 1
        measured = (energy[-1] / energy[0]) ** (1.0 / n)
        predicted = 1 + Omega ** 2 / 2
        error = abs(math.log(measured) - math.log(predicted)) / math.log(predicted)
        print("primer update: energy grows by %.8f per step, |lambda|^2 = 1 + (w_h dt)^2/2 = %.8f "
              "(relative difference of the rates %.2e)" % (measured, predicted, error))
        if error > args.growth_tol:
            failures.append("growth rate %.8f, predicted %.8f" % (measured, predicted))

    T = float(history[-1]["time"])
    if args.discrete_tol or args.exact:
        amplitude = V0 / wh
        # Newmark (trapezoidal) rotates (w_h u, v) rigidly; central difference starts with
        # u_1 = dt v0, so u_n = A sin(w_bar t_n) with A = dt v0 / sin(w_bar dt), and its
        # velocity is the staggered difference (u_n - u_(n-1)) / dt.
        if args.scheme == "newmark":
            def nodal(t):
                return amplitude * math.sin(wbar * t), V0 * math.cos(wbar * t)
        else:
            A = args.dt * V0 / math.sin(wbar * args.dt)

            def nodal(t):
                return (A * math.sin(wbar * t),
                        A * (math.sin(wbar * t) - math.sin(wbar * (t - args.dt))) / args.dt)
        worst_discrete, worst_exact, bound = 0.0, 0.0, 0.0
        for row in particles:
            X = float(row["X"])
            weights = tent_weights(X, h, args.cells)
            mode = sum(w * math.sin(K * i * h) for i, w in weights)
            u_d, v_d = (value * mode for value in nodal(T))
            u_e = V0 / W * math.sin(W * T) * math.sin(K * X)
            v_e = V0 * math.cos(W * T) * math.sin(K * X)
            u, v = float(row["u"]), float(row["v"])
            worst_discrete = max(worst_discrete, abs(u - u_d) / amplitude, abs(v - v_d) / V0)
            worst_exact = max(worst_exact, abs(u - u_e) / amplitude, abs(v - v_e) / V0)
            # What the discrete theory predicts for the difference: phase error, frequency
            # (amplitude) error and interpolation error of the mode between nodes.
            phase = abs(wbar - W) * T
            scheme = abs(nodal(T)[0] / (amplitude * math.sin(wbar * T)) - 1) if args.scheme != \
                "newmark" else 0.0
            bound = max(bound, phase + abs(W / wh - 1) + scheme + abs(mode - math.sin(K * X)))
        print("at t = %g: largest difference to the discrete solution %.2e, to the exact %.2e "
              "(predicted at most %.2e), relative to the amplitudes" % (T, worst_discrete,
                                                                      worst_exact, bound))
        if args.discrete_tol and worst_discrete > args.discrete_tol:
            failures.append("particles differ from the discrete solution by %.2e" % worst_discrete)
        if args.exact and worst_exact > 1.05 * bound:
            failures.append("particles differ from the exact solution by %.2e, more than the "
                            "predicted %.2e" % (worst_exact, bound))

    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
