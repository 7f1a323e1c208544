#!/usr/bin/env python3
"""Lame's thick-walled cylinder from a body-fitted mesh and from an image (the primer's
Fig. 1.6 claim, doc/verification/geometry.md).

Runs input/cylinder_lame_mesh.xml and input/cylinder_lame_image.xml with the grid, the mesh
and the image refined together: level k has 10 2^k grid cells per direction, a mesh of
8 2^k x 19 2^k elements (build/drivers/impm_mesh) and an image of 16 2^k pixels per side
(annulus_image.py), so that both bodies have about 152 4^k particles.  For every run it
measures, over the particles,

  e_u = RMS(u_r - u_r exact) / RMS(u_r exact),   e_s = RMS(sigma_rr - exact) / p,

at the reference positions X_p, and the rates between levels.  It asserts:

  - the mesh body's e_u converges at a rate within --mesh-rate (the last two levels'
    rate and the least-squares rate over all levels),
  - the mesh body's e_s decreases from level to level,
  - the image body's e_u converges no faster than --image-rate-max (a staircase boundary
    makes the error first order at best),
  - at the finest level the mesh body is at least --advantage times more accurate.

    lame_cylinder.py --impm build/drivers/impm --mesher build/drivers/impm_mesh \\
        --decks input [--levels 4] [--table FILE.md] [--plot FILE.png]
"""

import argparse
import math
import os
import shutil
import sys
import tempfile

from annulus_image import write_annulus
from impmrun import run_deck
import subprocess

E, P, A, B = 1.0e6, 1.0, 1.0, 2.0
NU = 0.3  # --nu sets it for the exact solution (the deck's own Poisson ratio)


def exact_ur(r):
    return (1 + NU) * P * A * A / (E * (B * B - A * A)) * ((1 - 2 * NU) * r + B * B / r)


def exact_srr(r):
    return P * A * A / (B * B - A * A) * (1 - B * B / (r * r))


def errors(rows):
    """(e_u, e_s, particles) of a particle table."""
    du = uu = ds = 0.0
    for w in rows:
        X, Y = float(w["X"]), float(w["Y"])
        r = math.hypot(X, Y)
        c, s = X / r, Y / r
        u = float(w["u_x"]) * c + float(w["u_y"]) * s
        srr = (float(w["stress_xx"]) * c * c + float(w["stress_yy"]) * s * s
               + 2 * float(w["stress_xy"]) * s * c)
        du += (u - exact_ur(r)) ** 2
        uu += exact_ur(r) ** 2
        ds += (srr - exact_srr(r)) ** 2
    return math.sqrt(du / uu), math.sqrt(ds / len(rows)) / P, len(rows)


def rate(e, k):
    return math.log(e[k - 1] / e[k], 2)


def fitted_rate(e):
    """Least-squares slope of -log2 e over the levels."""
    n = len(e)
    xs = list(range(n))
    ys = [-math.log(v, 2) for v in e]
    mx, my = sum(xs) / n, sum(ys) / n
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def run_levels(args, work):
    mesh, image = [], []
    for k in range(args.levels):
        cells = 10 * 2 ** k
        grid = "Grid/Cells={%d, %d}" % (cells, cells)
        exo = os.path.join(work, "annulus_%d.exo" % k)
        subprocess.run([args.mesher, "annulus", exo, "--radii", "1", "2", "--cells",
                        str(8 * 2 ** k), str(19 * 2 ** k), "--block", "cylinder"],
                       check=True, capture_output=True)
        out = run_deck(args.impm, os.path.join(args.decks, args.mesh_deck),
                       [grid, "Bodies/cylinder/Mesh File=" + exo, "Output/Exodus=false"]
                       + args.set)
        mesh.append(errors(out.table("_particles.csv")))
        out.remove()
        if args.mesh_only:
            print("level %d: %d cells; mesh %d particles e_u %.3e e_s %.3e"
                  % (k, cells, mesh[-1][2], mesh[-1][0], mesh[-1][1]), flush=True)
            continue
        pixels = 16 * 2 ** k
        png = os.path.join(work, "annulus_%d.png" % k)
        write_annulus(png, pixels)
        out = run_deck(args.impm, os.path.join(args.decks, "cylinder_lame_image.xml"),
                       [grid, "Bodies/cylinder/Image File=" + png,
                        "Bodies/cylinder/Pixel Size=%r" % (2.0 / pixels), "Output/Exodus=false"])
        image.append(errors(out.table("_particles.csv")))
        out.remove()
        print("level %d: %d cells; mesh %d particles e_u %.3e e_s %.3e; "
              "image %d particles e_u %.3e e_s %.3e"
              % (k, cells, mesh[-1][2], mesh[-1][0], mesh[-1][1], image[-1][2], image[-1][0],
                 image[-1][1]), flush=True)
    return mesh, image


def table(mesh, image):
    lines = ["| level | grid cells | mesh particles | mesh e_u | rate | mesh e_s | "
             "image particles | image e_u | rate | image e_s | image e_u / mesh e_u |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    eu_m = [m[0] for m in mesh]
    eu_i = [i[0] for i in image]
    for k, (m, i) in enumerate(zip(mesh, image)):
        rm = "%.2f" % rate(eu_m, k) if k else ""
        ri = "%.2f" % rate(eu_i, k) if k else ""
        lines.append("| %d | %d x %d | %d | %.3e | %s | %.3e | %d | %.3e | %s | %.3e | %.1f |"
                     % (k, 10 * 2 ** k, 10 * 2 ** k, m[2], m[0], rm, m[1], i[2], i[0], ri,
                        i[1], i[0] / m[0]))
    return "\n".join(lines) + "\n"


def plot(path, mesh, image):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for data, label, mark, colour in ((mesh, "mesh body (CPDI2 domains)", "o", "tab:blue"),
                                      (image, "image body (pixel domains)", "s", "tab:red")):
        ax.loglog([d[2] for d in data], [d[0] for d in data], mark + "-", color=colour,
                  label=label + ": $e_u$")
        ax.loglog([d[2] for d in data], [d[1] for d in data], mark + "--", color=colour,
                  label=label + r": $e_\sigma$", alpha=0.5)
    n0 = mesh[0][2]
    ns = [m[2] for m in mesh]
    ax.loglog(ns, [mesh[0][0] * n0 / n for n in ns], "k:", label="second order in h")
    ax.set_xlabel("particles")
    ax.set_ylabel("relative RMS error")
    ax.set_title("Lame cylinder: body-fitted mesh against image")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def mesh_errors_only(args, mesh):
    """The mesh body's e_u at each level against --max-errors and --min-errors."""
    eu = [m[0] for m in mesh]
    print("mesh e_u: %s; rates %s" % (" ".join("%.3e" % e for e in eu),
                                       " ".join("%.2f" % rate(eu, k) for k in range(1, len(eu)))))
    failures = []
    for k, e in enumerate(eu):
        if args.max_errors and not e <= args.max_errors[k]:
            failures.append("level %d: e_u %.3e above %g" % (k, e, args.max_errors[k]))
        if args.min_errors and not e >= args.min_errors[k]:
            failures.append("level %d: e_u %.3e below %g" % (k, e, args.min_errors[k]))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


def fine_grids(args):
    """The committed 8 x 19 mesh on grids finer than it: the mesh limits e_u, the grid must not
    spoil it.  Returns the exit status."""
    failures = []
    for cells in args.fine_grids:
        out = run_deck(args.impm, os.path.join(args.decks, "cylinder_lame_mesh.xml"),
                       ["Grid/Cells={%d, %d}" % (cells, cells), "Output/Exodus=false"])
        eu, es, n = errors(out.table("_particles.csv"))
        out.remove()
        print("%d x %d cells: %d particles, e_u %.3e, e_s %.3e" % (cells, cells, n, eu, es))
        if not eu <= args.max_error:
            failures.append("e_u %.3e above %g on %d x %d cells" % (eu, args.max_error, cells,
                                                                   cells))
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


def main():
    global NU
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--impm", required=True)
    ap.add_argument("--mesher", required=True)
    ap.add_argument("--decks", required=True)
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--mesh-rate", type=float, nargs=2, default=[1.7, 2.3])
    ap.add_argument("--image-rate-max", type=float, default=1.3)
    ap.add_argument("--advantage", type=float, default=3.0)
    ap.add_argument("--table")
    ap.add_argument("--plot")
    ap.add_argument("--fine-grids", type=int, nargs="+",
                    help="instead: the deck's own mesh on grids of these many cells a side, "
                         "finer than the mesh (nodes that its domains barely reach); e_u must "
                         "stay at or below --max-error")
    ap.add_argument("--max-error", type=float, default=1e-3)
    ap.add_argument("--mesh-deck", default="cylinder_lame_mesh.xml",
                    help="the mesh body's deck in --decks")
    ap.add_argument("--nu", type=float, default=NU,
                    help="the mesh deck's Poisson ratio, for the exact solution")
    ap.add_argument("--set", action="append", default=[], help="overrides for the mesh deck")
    ap.add_argument("--mesh-only", action="store_true",
                    help="the mesh body alone: its e_u at every level within --max-errors")
    ap.add_argument("--max-errors", type=float, nargs="+",
                    help="with --mesh-only: the largest e_u at each level")
    ap.add_argument("--min-errors", type=float, nargs="+",
                    help="with --mesh-only: the smallest e_u at each level (a method that locks)")
    args = ap.parse_args()
    NU = args.nu
    if args.fine_grids:
        sys.exit(fine_grids(args))
    work = os.path.abspath(tempfile.mkdtemp(prefix="lame-", dir="."))
    try:
        mesh, image = run_levels(args, work)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if args.mesh_only:
        sys.exit(mesh_errors_only(args, mesh))
    text = table(mesh, image)
    print(text)
    if args.table:
        with open(args.table, "w") as f:
            f.write(text)
    if args.plot:
        plot(args.plot, mesh, image)
    failures = []
    eu_m, eu_i = [m[0] for m in mesh], [i[0] for i in image]
    lo, hi = args.mesh_rate
    for name, r in (("last", rate(eu_m, len(eu_m) - 1)), ("fitted", fitted_rate(eu_m))):
        if not lo <= r <= hi:
            failures.append("mesh body: %s rate %.2f of e_u outside [%g, %g]" % (name, r, lo, hi))
    for k in range(1, len(mesh)):
        if not mesh[k][1] < mesh[k - 1][1]:
            failures.append("mesh body: e_s did not decrease at level %d" % k)
    r = fitted_rate(eu_i)
    if r > args.image_rate_max:
        failures.append("image body: rate %.2f of e_u above %g" % (r, args.image_rate_max))
    if not eu_i[-1] >= args.advantage * eu_m[-1]:
        failures.append("finest level: image e_u %.3e is not %g times mesh e_u %.3e"
                        % (eu_i[-1], args.advantage, eu_m[-1]))
    print("mesh rate: last %.2f fitted %.2f; image fitted rate %.2f; advantage %.1f"
          % (rate(eu_m, len(eu_m) - 1), fitted_rate(eu_m), r, eu_i[-1] / eu_m[-1]))
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
