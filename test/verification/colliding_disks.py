#!/usr/bin/python3
"""P3: two elastic disks (or, in 3-D, spheres) collide with no contact code (PROBLEMS.md P3).

Runs impm on the deck and asserts, from its outputs:
  - no interpenetration: at every output step, no particle centre of one body lies inside
    the current domain (a parallelogram or parallelepiped, from <prefix>_domains.exo) of a
    particle of the other body;
  - rebound: each disk's centre-of-mass velocity has reversed (both components) by the end;
  - separation: at the end the closest particle centres of the two disks are further apart
    than a particle spacing;
  - energy: the total energy stays within --energy-tolerance of its initial value.
With --plot, draws the energies (kinetic, strain, total) against time into a PNG.
Uses Debian's python3 with python3-numpy, python3-netcdf4 and python3-matplotlib.
"""

import argparse
import csv
import sys

import netCDF4
import numpy as np

from impmrun import run_deck


def exodus(path):
    d = netCDF4.Dataset(path)
    names = lambda v: [str(s) for s in netCDF4.chartostring(d[v][:])]
    nodal = {n: d["vals_nod_var%d" % (k + 1)][:] for k, n in enumerate(names("name_nod_var"))}
    element = {n: d["vals_elem_var%deb1" % (k + 1)][:] for k, n in enumerate(names("name_elem_var"))}
    return d, nodal, element


def inside(points, quads):
    """inside[i, j]: point i lies in the convex quadrilateral j (counter-clockwise corners)."""
    result = np.ones((len(points), len(quads)), dtype=bool)
    for k in range(4):
        a, b = quads[:, k, :], quads[:, (k + 1) % 4, :]
        edge = b - a
        rel = points[:, None, :] - a[None, :, :]
        cross = edge[None, :, 0] * rel[:, :, 1] - edge[None, :, 1] * rel[:, :, 0]
        result &= cross > 0
    return result


def inside_parallelepipeds(points, cells):
    """inside[i, j]: point i lies in the parallelepiped j, given by its HEX8 corners (corner 0
    at -r1 - r2 - r3, corners 1, 3 and 4 one edge away along r1, r2 and r3)."""
    origin = cells[:, 0, :]
    edges = np.stack([cells[:, 1, :] - origin, cells[:, 3, :] - origin, cells[:, 4, :] - origin],
                     axis=2)  # (cell, component, edge)
    inverse = np.linalg.inv(edges)
    rel = points[:, None, :] - origin[None, :, :]
    a = np.einsum("jke,ije->ijk", inverse, rel)  # coordinates along the edges
    return np.all((a > 0) & (a < 1), axis=2)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--impm", required=True)
    p.add_argument("--deck", required=True)
    p.add_argument("--set", action="append", default=[])
    p.add_argument("--energy-tolerance", type=float, default=0.05)
    p.add_argument("--plot", help="PNG of the energies against time")
    args = p.parse_args()

    out = run_deck(args.impm, args.deck, args.set, "impm-disks-")
    prefix = out.path("")
    failures = []

    points, pnodal, pelem = exodus(prefix + "_particles.exo")
    domains, dnodal, _ = exodus(prefix + "_domains.exo")
    body = pelem["body"][0].astype(int)
    connect = domains["connect1"][:] - 1
    dim = len(domains.dimensions["num_dim"])
    axes = "xyz"[:dim]
    test = inside if dim == 2 else inside_parallelepipeds
    X = np.stack([points["coord" + a][:] for a in axes], axis=1)
    C = np.stack([domains["coord" + a][:] for a in axes], axis=1)
    worst = 0
    for step in range(len(points["time_whole"][:])):
        x = X + np.stack([pnodal["displacement" + a.upper()][step] for a in axes], axis=1)
        corners = C + np.stack([dnodal["displacement" + a.upper()][step] for a in axes], axis=1)
        quads = corners[connect]
        # The detector must see each particle's own centre inside its own domain.
        own = np.diagonal(test(x, quads))
        if not own.all():
            failures.append("t = %g: %d particle centres outside their own domains (a wrong "
                            "domain file?)" % (points["time_whole"][step], int((~own).sum())))
        for a, b in ((0, 1), (1, 0)):
            count = int(test(x[body == b], quads[body == a]).sum())
            worst = max(worst, count)
            if count:
                failures.append("t = %g: %d particle centres of body %d inside domains of body %d"
                                % (points["time_whole"][step], count, b, a))
    print("interpenetration: %d particle centres inside the other body's domains at worst over %d "
          "output steps" % (worst, len(points["time_whole"][:])))

    rows = list(csv.DictReader(open(prefix + "_history.csv")))
    energy = [float(r["total_energy"]) for r in rows]
    change = max(abs(e - energy[0]) for e in energy) / energy[0]
    print("total energy: initial %.6g, final %.6g, largest relative change %.3e"
          % (energy[0], energy[-1], change))
    if change > args.energy_tolerance:
        failures.append("total energy changes by %.3e (allowed %g)" % (change, args.energy_tolerance))
    names = [k[len("v_cm_"):] for k in rows[0] if k.startswith("v_cm_")]
    for n in names:
        for c in ("v_cm_", "vy_cm_", "vz_cm_")[:dim]:
            v0, v1 = float(rows[0][c + n]), float(rows[-1][c + n])
            if abs(v0) < 1e-12:  # a component the bodies do not move along
                continue
            print("%s%s: %+.5f -> %+.5f" % (c, n, v0, v1))
            if not v0 * v1 < 0 or abs(v1) < 0.5 * abs(v0):
                failures.append("%s of %s has not reversed: %g -> %g" % (c, n, v0, v1))
    table = list(csv.DictReader(open(prefix + "_particles.csv")))
    final = {k: np.array([float(r[k]) for r in table]) for k in tuple(axes) + ("body", "r1_x")}
    xa = np.stack([final[a] for a in axes], axis=1)
    gap = np.min(np.linalg.norm(xa[final["body"] == 0][:, None, :] - xa[final["body"] == 1][None, :, :],
                                axis=2))
    spacing = 2 * np.max(np.abs(final["r1_x"]))
    print("final gap between the bodies' particle centres %.4f (particle spacing %.4f)" % (gap, spacing))
    if gap <= spacing:
        failures.append("the bodies have not separated: gap %.4f <= %.4f" % (gap, spacing))

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        t = [float(r["time"]) for r in rows]
        fig, ax = plt.subplots(figsize=(7, 4))
        for column, label in (("kinetic_energy", "kinetic"), ("strain_energy", "strain"),
                              ("total_energy", "total")):
            ax.plot(t, [float(r[column]) for r in rows], label=label)
        ax.set_xlabel("time")
        ax.set_ylabel("energy per unit thickness")
        ax.set_title("P3 colliding disks (%s)" % " ".join(args.set or ["deck as written"]))
        ax.legend()
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(args.plot, dpi=100)
    out.remove()
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
