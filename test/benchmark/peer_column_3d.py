#!/usr/bin/env python3
"""Writes the input of the C++ implicit MPM peer (geomechanics/mpm, analysis MPMImplicit3D)
for the 3-D column of doc/performance.md: under self-weight, 1-D confined compression,
exact u_y(Y) = -(rho g / E)(H Y - Y^2 / 2), top -rho g H^2 / (2E).

Grid: NX x NY x NX hexahedral cells (x, y = vertical, z); cell size h = H/NY;
the column fills the grid exactly (cross-section NX*h x NX*h, height H).
Particles: 2x2x2 per cell at the quarter points (offsets h/4, 3h/4).
BCs (nodal displacement constraints, value 0): bottom y=0 -> u_y = 0 (roller);
x=0 and x=W -> u_x = 0; z=0 and z=W -> u_z = 0 (lateral rollers).
Gravity (0, -g, 0). Linear elastic (LinearElastic3D), nu = 0 by default.

Load stepping: the peer's implicit solver applies the full gravity vector at
every step (its "gravity.ramping_time" is only honoured by the explicit
solver), so the "10 load steps" are 10 quasi-static Newmark steps
("quasi_static": true) at full gravity; step 1 reaches equilibrium, the
remaining ones re-check/re-solve the (tiny) residual.

Usage (the peer built from its sources in Release, without MPI, VTK or PETSc):
  python3 peer_column_3d.py --nx 10 --ny 125 --out c10x125
  OMP_NUM_THREADS=1 <peer build>/mpm -f c10x125/ -i input.json -p 1
Results: <out>/results/<uuid>/particles<step>.h5 (initial and final step); the relative L2
error of u_y over the particles against the exact solution is the accuracy compared.
"""
import argparse
import json
import os


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nx", type=int, default=4, help="cells across (x and z)")
    ap.add_argument("--ny", type=int, default=32, help="cells along the height (y)")
    ap.add_argument("--H", type=float, default=50.0, help="column height")
    ap.add_argument("--E", type=float, default=1.0e6)
    ap.add_argument("--nu", type=float, default=0.0)
    ap.add_argument("--rho", type=float, default=1.0)
    ap.add_argument("--g", type=float, default=10.0)
    ap.add_argument("--nsteps", type=int, default=10, help="load steps")
    ap.add_argument("--dt", type=float, default=1.0,
                    help="time step (irrelevant for quasi-static)")
    ap.add_argument("--linear", action="store_true",
                    help='"nonlinear": false (one linear solve per step) '
                         'instead of the default Newton-Raphson loop')
    ap.add_argument("--solver", default="ldlt", choices=["ldlt", "lu", "cg"],
                    help="ldlt/lu -> DirectEigen (SimplicialLDLT / SparseLU); "
                         "cg -> IterativeEigen")
    ap.add_argument("--verbosity", type=int, default=1,
                    help="scheme_settings verbosity (2 prints NR norms)")
    ap.add_argument("--uuid", default="column3d")
    ap.add_argument("--out", required=True, help="output directory")
    a = ap.parse_args()

    nx, ny, nz = a.nx, a.ny, a.nx
    h = a.H / ny
    W = nx * h
    os.makedirs(a.out, exist_ok=True)

    # ---------------- mesh (Ascii3D): "nnodes ncells", coords, cell node ids
    def nid(i, j, k):  # i: x, j: y (vertical), k: z
        return i + (nx + 1) * (k + (nz + 1) * j)

    nnodes = (nx + 1) * (ny + 1) * (nz + 1)
    ncells = nx * ny * nz
    with open(os.path.join(a.out, "mesh.txt"), "w") as f:
        f.write("%d %d\n" % (nnodes, ncells))
        for j in range(ny + 1):
            for k in range(nz + 1):
                for i in range(nx + 1):
                    f.write("%.12g %.12g %.12g\n" % (i * h, j * h, k * h))
        # ED3H8 ordering: 0(0,0,0) 1(1,0,0) 2(1,1,0) 3(0,1,0) 4..7 same at z+1
        for j in range(ny):
            for k in range(nz):
                for i in range(nx):
                    c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k),
                         nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1),
                         nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
                    f.write(" ".join(map(str, c)) + "\n")

    # ---------------- particles: 2x2x2 per cell at quarter points
    offs = (0.25 * h, 0.75 * h)
    with open(os.path.join(a.out, "particles.txt"), "w") as f:
        f.write("%d\n" % (8 * ncells))
        for j in range(ny):
            for k in range(nz):
                for i in range(nx):
                    for oy in offs:
                        for oz in offs:
                            for ox in offs:
                                f.write("%.12g %.12g %.12g\n" %
                                        (i * h + ox, j * h + oy, k * h + oz))

    # ---------------- displacement constraints: "node dir value"
    ncons = 0
    with open(os.path.join(a.out, "displacement-constraints.txt"), "w") as f:
        for j in range(ny + 1):
            for k in range(nz + 1):
                for i in range(nx + 1):
                    n = nid(i, j, k)
                    if i == 0 or i == nx:
                        f.write("%d 0 0\n" % n); ncons += 1
                    if j == 0:
                        f.write("%d 1 0\n" % n); ncons += 1
                    if k == 0 or k == nz:
                        f.write("%d 2 0\n" % n); ncons += 1

    if a.solver == "cg":
        solver = {"dof": "displacement", "solver_type": "IterativeEigen",
                  "sub_solver_type": "cg", "preconditioner_type": "none",
                  "max_iter": 10000, "tolerance": 1e-12, "verbosity": 0}
    else:
        solver = {"dof": "displacement", "solver_type": "DirectEigen",
                  "sub_solver_type": a.solver, "max_iter": 1,
                  "tolerance": 1e-12, "verbosity": 1}

    cfg = {
        "title": "3D column under self-weight, %dx%dx%d cells" % (nx, ny, nz),
        "mesh": {
            "mesh": "mesh.txt",
            "io_type": "Ascii3D",
            "check_duplicates": False,
            "isoparametric": False,
            "node_type": "N3D",
            "cell_type": "ED3H8",
            "boundary_conditions": {
                "displacement_constraints": [
                    {"file": "displacement-constraints.txt"}]
            }
        },
        "particles": [{
            "generator": {
                "type": "file",
                "io_type": "Ascii3D",
                "particle_type": "P3D",
                "material_id": 0,
                "pset_id": 0,
                "check_duplicates": False,
                "location": "particles.txt"
            }
        }],
        "materials": [{
            "id": 0, "type": "LinearElastic3D", "density": a.rho,
            "youngs_modulus": a.E, "poisson_ratio": a.nu
        }],
        "external_loading_conditions": {"gravity": [0.0, -a.g, 0.0]},
        "analysis": {
            "type": "MPMImplicit3D",
            "mpm_scheme": "newmark",
            "scheme_settings": {
                "nonlinear": not a.linear,
                "quasi_static": True,
                "beta": 0.25, "gamma": 0.5,
                "max_iteration": 20,
                "displacement_tolerance": 1.0e-10,
                "residual_tolerance": 1.0e-10,
                "relative_residual_tolerance": 1.0e-6,
                "verbosity": a.verbosity
            },
            "locate_particles": True,
            "pressure_smoothing": False,
            "velocity_update": "flip",
            "dt": a.dt,
            "nsteps": a.nsteps,
            "uuid": a.uuid,
            "linear_solver": {
                "assembler_type": "EigenImplicit3D",
                "solver_settings": [solver]
            },
            "damping": {"type": "None", "damping_factor": 0.0}
        },
        "post_processing": {
            "path": "results/",
            "output_steps": a.nsteps
        }
    }
    with open(os.path.join(a.out, "input.json"), "w") as f:
        json.dump(cfg, f, indent=2)

    uex = -a.rho * a.g * a.H ** 2 / (2 * a.E)
    print("cells %d (%dx%dx%d), h=%g, W=%g, nodes %d, particles %d, "
          "constrained dofs %d, exact u_top=%.6g" %
          (ncells, nx, ny, nz, h, W, nnodes, 8 * ncells, ncons, uex))


if __name__ == "__main__":
    main()
