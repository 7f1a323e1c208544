#!/usr/bin/env python3
"""Checks that run the impm driver as a user would and judge its outputs.

  convergence  run a deck at several grid sizes; assert the RMS error at each size and the
               observed rate between successive sizes (PROBLEMS.md: r = log2(e_2h / e_h); for
               other ratios r = log(e_H / e_h) / log(H / h))
  ranks        run a deck on several rank counts; assert the particle CSVs agree
  fails        run a deck that must be rejected; assert the exit status, that the message
               is printed, and that no output file was written
  uniform      run a deck whose exact solution is a homogeneous deformation; assert that
               every particle carries the same F, stress and J

Only the Python standard library is used.
"""

import argparse
import csv
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile


def run_impm(args, deck, out_dir, sets, np=1, options=()):
    cmd = []
    if np > 1:
        cmd += shlex.split(args.mpiexec or "mpiexec") + [str(np)]
    cmd += [args.impm, "--output-dir", out_dir] + list(options)
    for s in sets:
        cmd += ["--set", s]
    cmd.append(deck)
    return subprocess.run(cmd, capture_output=True, text=True)


def read_csv(path):
    with open(path, newline="") as f:  # a restart's notes are comment lines
        rows = list(csv.DictReader(line for line in f if not line.startswith("# ")))
    return rows


def stem(deck):
    return os.path.splitext(os.path.basename(deck))[0]


def convergence(args):
    errors, table, field_errors = [], [], []
    failures = []
    if not args.rate and args.exact is None:
        sys.exit("convergence needs --rate or --exact")
    for n in args.cells:
        out = tempfile.mkdtemp(prefix="impm-conv-", dir=".")
        sets = ["Grid/Cells=" + args.grid.replace("%d", str(n)), "Discretization/Method=" + args.method,
                "Verification/Maximum RMS Error=0", "Verification/Reaction Tolerance=0",
                "Solver/Print Iterations=false"] + args.set
        if args.time_step:  # proportional to the cell size
            sets.append("Time Integration/Time Step=%r" % (args.time_step * args.cells[0] / n))
        r = run_impm(args, args.deck, out, sets, args.np)
        if r.returncode != 0:
            print(r.stdout, r.stderr)
            sys.exit("impm failed at %d cells" % n)
        row = read_csv(os.path.join(out, stem(args.deck) + "_verification.csv"))[0]
        history = read_csv(os.path.join(out, stem(args.deck) + "_history.csv"))
        energy = [float(r["total_energy"]) for r in history]
        change = max(abs(e - energy[0]) for e in energy) / energy[0] if energy[0] else 0.0
        if args.energy_balance is not None:
            # external work = strain energy + kinetic energy + dissipation, at every step
            work = max(abs(float(r["external_work"])) for r in history)
            imbalance = max(abs(float(r["energy_balance"])) for r in history) / work
            print("energy balance at %d cells: largest |total - external work| = %.2e of the "
                  "largest external work" % (n, imbalance))
            if imbalance > args.energy_balance:
                failures.append("energy balance %.2e at %d cells (allowed %g)"
                                % (imbalance, n, args.energy_balance))
        if args.field:
            particles = read_csv(os.path.join(out, stem(args.deck) + "_particles.csv"))
            field_errors.append(field_error(particles, *args.field))
        shutil.rmtree(out)
        if args.energy_drift is not None and change > args.energy_drift:
            failures.append("total energy changes by %.2e at %d cells (allowed %g)"
                            % (change, n, args.energy_drift))
        if args.energy_loss is not None and energy[-1] > (1 - args.energy_loss) * energy[0]:
            failures.append("total energy lost only %.2e at %d cells (expected at least %g)"
                            % (1 - energy[-1] / energy[0], n, args.energy_loss))
        e = float(row["rms_error"])
        errors.append(e)
        table.append((n, int(row["points"]), e, float(row["F0"]), float(row["FL"]), change))
    print("%-6s %-7s %-12s %-6s %-20s %-20s %-10s" % ("cells", "points", "rms_error", "rate", "F0",
                                                     "FL", "energy"))
    for k, (n, pts, e, f0, fl, change) in enumerate(table):
        rate = (math.log(errors[k - 1] / e) / math.log(args.cells[k] / args.cells[k - 1])
                if k else float("nan"))
        print("%-6d %-7d %-12.4e %-6.3f %-20.15g %-20.15g %-10.2e" % (n, pts, e, rate, f0, fl, change))
        if args.exact is not None:
            if e > args.exact:
                failures.append("RMS error %.4e at %d cells: not exact to %g" % (e, n, args.exact))
        elif k and not (args.rate[0] <= rate <= args.rate[1]):
            failures.append("rate %.3f between %d and %d cells is outside [%g, %g]"
                            % (rate, table[k - 1][0], n, args.rate[0], args.rate[1]))
        if args.max_error and e > args.max_error[k]:
            failures.append("RMS error %.4e at %d cells is above %g" % (e, n, args.max_error[k]))
        if args.min_error and e < args.min_error:
            failures.append("RMS error %.4e at %d cells is below %g: the method was expected "
                            "to be inexact here" % (e, n, args.min_error))
        if args.reactions:
            f0_exact, fl_exact, tol0, order = args.reactions
            tol = tol0 / 2 ** (order * k)  # the bound shrinks with h^order
            for name, value, exact in (("F0", f0, f0_exact), ("FL", fl, fl_exact)):
                if abs(value - exact) > tol:
                    failures.append("%s = %.15g at %d cells differs from %.15g by more than %g"
                                    % (name, value, n, exact, tol))
    if args.field:
        failures += check_field(args, field_errors)
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def field_error(particles, column, expression, scale):
    """RMS over the particles of (column - expression(X, Y)) / scale."""
    total = 0.0
    for p in particles:
        names = {"X": float(p["X"]), "Y": float(p.get("Y", 0.0)), "math": math}
        total += ((float(p[column]) - eval(expression, {"__builtins__": {}}, names)) / float(scale)) ** 2
    return math.sqrt(total / len(particles))


def check_field(args, errors):
    failures = []
    print("%s error against %s, relative to %s:" % tuple(args.field))
    for k, e in enumerate(errors):
        rate = (math.log(errors[k - 1] / e) / math.log(args.cells[k] / args.cells[k - 1])
                if k else float("nan"))
        print("  %-6d %-12.4e %-6.3f" % (args.cells[k], e, rate))
        if args.field_max_error and e > args.field_max_error[k]:
            failures.append("%s error %.4e at %d cells is above %g"
                            % (args.field[0], e, args.cells[k], args.field_max_error[k]))
        if k and args.field_rate and not (args.field_rate[0] <= rate <= args.field_rate[1]):
            failures.append("%s error rate %.3f between %d and %d cells is outside [%g, %g]"
                            % (args.field[0], rate, args.cells[k - 1], args.cells[k],
                               args.field_rate[0], args.field_rate[1]))
    return failures


def run_tables(args, sets, np, prefix, exodus=None):
    """Runs the deck with the --set overrides in a fresh directory (iterations not printed)
    and returns its particle table and history; exits with impm's output when it fails.
    With `exodus` a dict, the time-step variables of the particles' Exodus file go in it."""
    out = tempfile.mkdtemp(prefix=prefix, dir=".")
    r = run_impm(args, args.deck, out, ["Solver/Print Iterations=false"] + sets, np)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        sys.exit("impm failed")
    particles = read_csv(os.path.join(out, stem(args.deck) + "_particles.csv"))
    history = read_csv(os.path.join(out, stem(args.deck) + "_history.csv"))
    if exodus is not None:
        exodus.update(exodus_variables(os.path.join(out, stem(args.deck) + "_particles.exo")))
    shutil.rmtree(out)
    return particles, history


def exodus_variables(path):
    """The time-step variables of an Exodus file by name (nodal ones, the first block's
    element ones, global ones), each the list of its values over all time steps (ncdump,
    17 digits)."""
    dump = subprocess.run(["ncdump", "-p", "9,17", path], capture_output=True, text=True,
                          check=True).stdout
    arrays = dict(re.findall(r"\n (\w+) =\s*(.*?);", dump[dump.index("\ndata:"):], re.S))
    names = lambda key: re.findall(r'"([^"]*)"', arrays.get(key, ""))
    values = lambda key: [float(v) for v in arrays[key].split(",")]
    variables = {}
    for kind, key in (("nod", "vals_nod_var%d"), ("elem", "vals_elem_var%deb1"),
                      ("glo", None)):
        for k, name in enumerate(names("name_%s_var" % kind)):
            if key:
                variables[name] = values(key % (k + 1))
            else:
                variables[name] = values("vals_glo_var")[k::len(names("name_glo_var"))]
    return variables


def uniform(args):
    """The particle fields of a homogeneous deformation must be equal at every particle: the
    spread (max - min) of each column, relative to 1 for F and J and to the largest stress
    magnitude for stresses, must stay below --rtol."""
    rows, history = run_tables(args, args.set, args.np, "impm-uniform-")
    stresses = [c for c in args.columns if c.startswith("stress")]
    stress_scale = max(abs(float(p[c])) for p in rows for c in stresses) if stresses else 1.0
    failures = []
    for c in args.columns:
        values = [float(p[c]) for p in rows]
        scale = stress_scale if c.startswith("stress") else 1.0
        spread = (max(values) - min(values)) / scale
        print("%-10s mean %-22.15g spread %.2e" % (c, sum(values) / len(values), spread))
        if spread > args.rtol:
            failures.append("%s varies by %.2e over %d particles (allowed %g)"
                            % (c, spread, len(rows), args.rtol))
    for name, width in args.reaction:
        # The support's force on a y face of reference width W (negative W: the face whose
        # outward normal is -y): sigma_yy F_xx W.
        mean = lambda c: sum(float(p[c]) for p in rows) / len(rows)
        expected = mean("stress_yy") * mean("F_xx") * float(width)
        value = float(history[-1][name])
        print("%s = %.15g, sigma_yy F_xx W = %.15g" % (name, value, expected))
        if abs(value - expected) > args.rtol * 10 * abs(expected):
            failures.append("%s = %.15g differs from sigma_yy F_xx W = %.15g" % (name, value, expected))
    if args.total_volume is not None:
        total = sum(float(p["volume"]) for p in rows)
        print("total volume %.15g, expected %.15g" % (total, args.total_volume))
        if abs(total - args.total_volume) > args.rtol * abs(args.total_volume):
            failures.append("the particle volumes sum to %.15g, expected %.15g"
                            % (total, args.total_volume))
    for name, value in args.expect:
        mean = sum(float(p[name]) for p in rows) / len(rows)
        if abs(mean - float(value)) > args.rtol * max(1.0, abs(float(value))):
            failures.append("%s = %.15g, expected %s" % (name, mean, value))
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def translation(args):
    """A rigid translation at velocity V: at the last step every particle and every tracked
    domain corner (columns c<k>_x, c<k>_y against c0<k>_x, c0<k>_y) has moved by V t, to
    --atol."""
    rows, history = run_tables(args, args.set, args.np, "impm-translation-")
    t = float(history[-1]["time"])
    corners = sorted({int(c[1:].split("_")[0]) for c in rows[0] if c.startswith("c")
                      and c[1] != "0" and c.endswith("_x")})
    pairs = [("u_x", None, args.velocity[0]), ("u_y", None, args.velocity[1])]
    for k in corners:
        pairs += [("c%d_x" % k, "c0%d_x" % k, args.velocity[0]),
                  ("c%d_y" % k, "c0%d_y" % k, args.velocity[1])]
    worst = 0.0
    for p in rows:
        for now, then, v in pairs:
            moved = float(p[now]) - (float(p[then]) if then else 0.0)
            worst = max(worst, abs(moved - v * t))
    print("t = %g: %d particles, %d corners each; largest error of the translation %.2e"
          % (t, len(rows), len(corners), worst))
    if not corners and args.corners:
        print("FAIL: the particles carry no corners")
        sys.exit(1)
    if worst > args.atol:
        print("FAIL: the translation is off by %.2e (allowed %g)" % (worst, args.atol))
        sys.exit(1)


def history(args):
    """Every row of a history column lies in [--min, --max] (an explicit run's linear
    iterations, say); with --last, the last row's (the end of a run)."""
    _, rows = run_tables(args, args.set, args.np, "impm-history-")
    values = [float(h[args.column]) for h in (rows[-1:] if args.last else rows)]
    print("%s over %d steps: min %g max %g" % (args.column, len(values), min(values), max(values)))
    if min(values) < args.min or max(values) > args.max:
        print("FAIL: %s leaves [%g, %g]" % (args.column, args.min, args.max))
        sys.exit(1)


def exclusive(args):
    """A second run on the output directory of a run under way is refused before it writes
    (one line naming the other process, exit 1); the first ends as if alone, its history one
    row per step, and leaves no lock file behind."""
    import time
    out = os.path.abspath(os.path.join(tempfile.mkdtemp(prefix="impm-exclusive-", dir="."), "out"))
    lock = os.path.join(out, ".impm.lock")
    first = subprocess.Popen([args.impm, "--output-dir", out, "--quiet", args.deck],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    for _ in range(3000):  # up to 30 s for the first run to take the lock
        if os.path.exists(lock) or first.poll() is not None:
            break
        time.sleep(0.01)
    second = run_impm(args, args.deck, out, [])
    out1, err1 = first.communicate()
    print(second.stderr.strip())
    problems = []
    if not os.path.exists(lock) and first.returncode is None:
        problems.append("the first run took no lock")
    lines = [l for l in second.stderr.splitlines() if l.startswith("impm:")]
    if second.returncode != 1 or len(lines) != 1 or "is in use by another impm run (process" \
            not in lines[0]:
        problems.append("the second run: exit %d, %s" % (second.returncode, second.stderr[-300:]))
    if first.returncode != 0:
        problems.append("the first run failed: %s" % err1[-300:])
    rows = read_csv(os.path.join(out, stem(args.deck) + "_history.csv"))
    steps = [int(float(r["step"])) for r in rows]
    if steps != list(range(len(steps))):
        problems.append("the history's steps are not 0, 1, 2, ...: %s" % steps[:20])
    if os.path.exists(lock):
        problems.append("the lock file remains")
    for p in problems:
        print("CHECK FAILED:", p)
    shutil.rmtree(os.path.dirname(out), ignore_errors=True)
    sys.exit(1 if problems else 0)


def extreme(args):
    """The largest (--stat max) or smallest (--stat min) value of a particle column at the
    end of the run lies in [--min, --max] (a runout, a settlement)."""
    rows, _ = run_tables(args, args.set, args.np, "impm-extreme-")
    values = [float(r[args.column]) for r in rows]
    value = max(values) if args.stat == "max" else min(values)
    print("%s of %s over %d particles: %.10g" % (args.stat, args.column, len(values), value))
    if not args.min <= value <= args.max:
        print("CHECK FAILED: %s of %s leaves [%g, %g]" % (args.stat, args.column, args.min,
                                                          args.max))
        sys.exit(1)


# The columns of a particle's motion (displacement, position, tracked corners) and of a
# body's extent: an explicit step on a fixed grid may let the motion wait and map the sum of
# several steps' increments at once, which moves them by round-off (solver/DynamicStepper).
MOTION_COLUMN = re.compile(r"^(x|y|u|u_x|u_y|corner\d+_[xy]|[xy]_(min|max)_.*)$")


def motion_scale(rows):
    """The largest |value| of the motion columns (the body's extent: a displacement's
    round-off is that of the positions it is the difference of)."""
    return max((abs(float(r[c])) for r in rows for c in r if MOTION_COLUMN.match(c)),
               default=0.0)


def motion_round_off(full, pairs, rtol=1e-13):
    """Where the second row of each pair (a run with few history rows) differs from the first
    (the same step, or place in the table, of the run with a row every step): in a column
    that is not of the motion, or in one that is by more than rtol of motion_scale(full);
    one message per row."""
    motion = [c for c in (full[0] if full else {}) if MOTION_COLUMN.match(c)]
    scale = motion_scale(full)
    failures = []
    for a, b in pairs:
        off = [c for c in b if b[c] != a.get(c) and not (
            c in motion and abs(float(b[c]) - float(a[c])) <= rtol * scale)]
        if off:
            failures.append(", ".join("%s %s (a row every step: %s)" % (c, b[c], a.get(c))
                                      for c in off))
    return failures


def history_every(args):
    """Output/History Every = N keeps the history rows of steps 0, N, 2N, ... and the last,
    each the very row (every column, as written) of the run with a row per step, and changes
    nothing else: the particle tables are the same.  Positions and displacements may differ
    by round-off (MOTION_COLUMN)."""
    every = "Output/History Every=%d" % args.every
    full_exodus, thin_exodus = {}, {}
    full_particles, full = run_tables(args, args.set, args.np, "impm-history-every-",
                                      full_exodus)
    thin_particles, thin = run_tables(args, args.set + [every], args.np, "impm-history-every-",
                                      thin_exodus)
    steps = [int(row["step"]) for row in full]
    expected = [s for s in steps if s % args.every == 0 or s == steps[-1]]
    got = [int(row["step"]) for row in thin]
    failures = []
    if got != expected:
        failures.append("rows at steps %s, expected %s" % (got, expected))
    by_step = {int(row["step"]): row for row in full}
    pairs = [(by_step.get(int(row["step"]), {}), row) for row in thin]
    failures += ["history: " + f for f in motion_round_off(full, pairs)]
    if len(thin_particles) != len(full_particles):
        failures.append("the particle tables have %d and %d rows"
                        % (len(thin_particles), len(full_particles)))
    failures += ["particles: " + f for f in motion_round_off(
        full_particles, list(zip(full_particles, thin_particles)))]
    # Every output step's particles (Exodus), also those between the history's rows.
    for name, values in full_exodus.items():
        other = thin_exodus.get(name, [])
        tolerance = 1e-13 * motion_scale(full_particles) if name.startswith("displacement") else 0
        if len(other) != len(values) or not all(
                abs(a - b) <= tolerance or (math.isnan(a) and math.isnan(b))
                for a, b in zip(values, other)):
            failures.append("particles' Exodus variable %s differs" % name)
    print("%d of %d rows kept (every %d steps and the last)" % (len(got), len(full), args.every))
    for f in failures[:5]:
        print("FAIL:", f)
    sys.exit(1 if failures or len(expected) >= len(steps) else 0)


def energy(args):
    """Runs a deck and checks its energy balance: the largest |energy_balance| (kinetic +
    strain + dissipated - external work) over the largest external work, at any step."""
    _, history = run_tables(args, args.set, args.np, "impm-energy-")
    work = max(abs(float(h["external_work"])) for h in history)
    imbalance = max(abs(float(h["energy_balance"])) for h in history) / work
    last = history[-1]
    print("external work %.6g = kinetic %.6g + strain %.6g + dissipation %.6g + imbalance %.6g; "
          "largest imbalance %.3e of the work" % (
              float(last["external_work"]), float(last["kinetic_energy"]),
              float(last["strain_energy"]), float(last["dissipation"]),
              -float(last["energy_balance"]), imbalance))
    if imbalance > args.tolerance:
        print("FAIL: energy balance %.3e above %g" % (imbalance, args.tolerance))
        sys.exit(1)


def unloading(args):
    """A homogeneous deck that unloads at its end: run it to its peak (--peak-set) and as
    written; between the two the response must be elastic: the Kirchhoff stress
    tau_yy = J sigma_yy changes by --modulus times the change of ln F_yy (Hencky elasticity,
    uniaxial plane strain) and the plastic strain does not change."""
    means = []
    for sets in (args.peak_set, []):
        rows, _ = run_tables(args, sets, 1, "impm-unload-")
        means.append({c: sum(float(p[c]) for p in rows) / len(rows)
                      for c in ("J", "stress_yy", "F_yy", args.plastic)})
    peak, end = means
    slope = ((end["J"] * end["stress_yy"] - peak["J"] * peak["stress_yy"])
             / (math.log(end["F_yy"]) - math.log(peak["F_yy"])))
    change = abs(end[args.plastic] - peak[args.plastic])
    print("unloading from F_yy %.6f to %.6f: d tau_yy / d ln F_yy = %.12g (elastic %.12g), "
          "plastic strain %.15g -> %.15g" % (peak["F_yy"], end["F_yy"], slope, args.modulus,
                                              peak[args.plastic], end[args.plastic]))
    failures = []
    if abs(slope / args.modulus - 1) > args.rtol:
        failures.append("unloading slope %.12g is not the elastic %.12g" % (slope, args.modulus))
    if change > 1e-14 or peak[args.plastic] <= 0:
        failures.append("the plastic strain must be positive and unchanged on unloading")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def linear_iterations_differ(histories, within):
    """A message for each rank count on which some step's Krylov iteration count differs
    from the first run's by more than `within` (an exact preconditioner on any number of
    ranks keeps them equal), or on which the steps are not the same."""
    runs = list(histories.items())
    base_np, base = runs[0]
    failures = []
    for np, history in runs[1:]:
        a = [int(float(r["linear_iterations"])) for r in base]
        b = [int(float(r["linear_iterations"])) for r in history]
        worst = max((abs(x - y) for x, y in zip(a, b)), default=0)
        print("%d ranks vs %d: linear iterations %d against %d over the run, at most %d apart "
              "in a step" % (np, base_np, sum(b), sum(a), worst))
        if len(a) != len(b) or worst > within:
            failures.append("linear iterations on %d ranks differ from %d ranks' by %d in a step "
                            "(allowed: %d)" % (np, base_np, worst, within))
    return failures


def ranks(args):
    results, histories, conserved_failures = {}, {}, []
    for np in args.np:
        out = tempfile.mkdtemp(prefix="impm-np%d-" % np, dir=".")
        r = run_impm(args, args.deck, out, ["Solver/Print Iterations=false"] + args.set, np,
                     ["--verbose"] if args.expect_log else [])
        if r.returncode != 0:
            print(r.stdout, r.stderr)
            sys.exit("impm failed on %d ranks" % np)
        results[np] = read_csv(os.path.join(out, stem(args.deck) + "_particles.csv"))
        history = read_csv(os.path.join(out, stem(args.deck) + "_history.csv"))
        histories[np] = history
        shutil.rmtree(out)
        if np > 1 and args.expect_log:
            found = re.findall(args.expect_log, r.stdout)
            print("%d ranks: %d log lines match %r%s" % (np, len(found), args.expect_log,
                  "".join("\n  " + f for f in found[:5])))
            if not found:
                conserved_failures.append("on %d ranks the log does not match %r"
                                          % (np, args.expect_log))
        for c in args.conserved:
            values = [float(r[c]) for r in history]
            drift = max(abs(v - values[0]) for v in values) / max(abs(values[0]), 1e-300)
            print("%d ranks: %s changes by %.2e relative over %d steps" % (np, c, drift, len(values) - 1))
            if drift > 1e-13:
                conserved_failures.append("%s not conserved on %d ranks: relative change %.2e"
                                          % (c, np, drift))
    base_np = args.np[0]
    base = results[base_np]
    failures = conserved_failures
    if args.linear_iterations_within is not None:
        failures += linear_iterations_differ(histories, args.linear_iterations_within)
    columns = list(base[0].keys())
    for np in args.np[1:]:
        other = results[np]
        if len(other) != len(base):
            failures.append("%d particles on %d ranks, %d on %d" % (len(other), np, len(base), base_np))
            continue
        worst, skipped = 0.0, []
        for c in columns:
            a = [float(row[c]) for row in base]
            b = [float(row[c]) for row in other]
            scale = max(max(abs(v) for v in a), 1e-300)
            absolute = max(abs(x - y) for x, y in zip(a, b))
            diff = absolute / scale
            if scale <= args.atol and absolute <= args.atol:  # a zero column (u_x of P1, say)
                skipped.append(c)
                continue
            worst = max(worst, diff)
            if diff > args.rtol:
                failures.append("column %s differs by %.3e (relative to its largest value) between "
                                "%d and %d ranks" % (c, diff, base_np, np))
        print("%d ranks vs %d: largest relative difference %.3e over %d particles%s"
              % (np, base_np, worst, len(base),
                 "; columns of round-off (|values| <= %g): %s" % (args.atol, " ".join(skipped))
                 if skipped else ""))
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def non_finite_history(rows):
    """Values that are not finite in the history, but for columns that are NaN in every row
    (a reaction the deck has no support for)."""
    problems = []
    for c in rows[0].keys() if rows else []:
        values = [float(r[c]) for r in rows]
        if all(math.isnan(v) for v in values):
            continue
        bad = [k for k, v in enumerate(values) if not math.isfinite(v)]
        if bad:
            problems.append("history column %s is not finite in row %d" % (c, bad[0]))
    return problems


def non_finite_exodus(path):
    """Time-step variables (vals_*) of an Exodus file that hold NaN or inf (python3-netcdf4,
    which build.sh installs).  A series that is NaN at every time step is a quantity that
    does not apply (the force FL of a bar without a Robin end at its right), not a failure."""
    import netCDF4
    import numpy
    problems = []
    with netCDF4.Dataset(path) as d:
        for name, var in d.variables.items():
            if not name.startswith("vals_"):
                continue
            values = numpy.asarray(var[:], dtype=float).reshape(var.shape[0], -1)
            absent = numpy.all(numpy.isnan(values), axis=0)  # per entry, over the time steps
            if not numpy.all(numpy.isfinite(values[:, ~absent])):
                problems.append("%s: %s is not finite" % (os.path.basename(path), name))
    return problems


def fails(args):
    out = os.path.join(tempfile.mkdtemp(prefix="impm-bad-", dir="."), "out")
    r = run_impm(args, args.deck, out, args.set, args.np, args.option)
    sys.stdout.write(r.stdout)
    sys.stdout.write(r.stderr)
    problems = []
    if r.returncode != args.exit:
        problems.append("exit status %d, expected %d" % (r.returncode, args.exit))
    if args.outputs_remain:
        # A numerical failure keeps what was written: complete history rows, readable Exodus.
        history = os.path.join(out, stem(args.deck) + "_history.csv")
        rows = read_csv(history) if os.path.exists(history) else []
        if len(rows) < args.steps_done + 1:
            problems.append("the history holds %d rows, expected the initial one and %d steps"
                            % (len(rows), args.steps_done))
        problems += non_finite_history(rows)
        for f in sorted(os.listdir(out)) if os.path.exists(out) else []:
            if f.endswith(".exo"):
                if subprocess.run(["ncdump", "-h", os.path.join(out, f)],
                                  capture_output=True).returncode != 0:
                    problems.append("%s is not a readable netCDF/Exodus file" % f)
                else:
                    problems += non_finite_exodus(os.path.join(out, f))
        print("outputs kept: %d history rows" % len(rows))
    elif os.path.exists(out) and os.listdir(out):
        problems.append("output files were written: %s" % ", ".join(sorted(os.listdir(out))))
    # impm's own lines (mpiexec adds its own when a rank exits with an error).
    own = [l for l in r.stderr.splitlines() if l.startswith("impm:")]
    if len(own) != 1 and args.exit == 1:
        problems.append("the error is not one line (%d lines from impm)" % len(own))
    shutil.rmtree(os.path.dirname(out))
    if args.same_error_with:
        # The same deck with other settings that must not change the failure or its message.
        again = os.path.join(tempfile.mkdtemp(prefix="impm-bad-", dir="."), "out")
        r2 = run_impm(args, args.deck, again, args.set + args.same_error_with, args.np)
        own2 = [l for l in r2.stderr.splitlines() if l.startswith("impm:")]
        if own2[-1:] != own[-1:]:
            problems.append("with %s the error is %s, not %s"
                            % (", ".join(args.same_error_with), own2[-1:], own[-1:]))
        shutil.rmtree(os.path.dirname(again))
    for p in problems:
        print("CHECK FAILED:", p)
    sys.exit(1 if problems else 0)


def newton(args):
    """Parses the Newton log (Print Iterations) and checks the order of convergence."""
    out = tempfile.mkdtemp(prefix="impm-newton-", dir=".")
    r = run_impm(args, args.deck, out, ["Solver/Print Iterations=true"] + args.set, args.np)
    shutil.rmtree(out)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        sys.exit("impm failed")
    solves, current = [], None
    for line in r.stdout.splitlines():
        m = re.match(r"\s*newton\s+(\d+)\s+\|R\| = (\S+)", line)
        if not m:
            continue
        if int(m.group(1)) == 0:
            current = []
            solves.append(current)
        current.append(float(m.group(2)))
    failures = []
    # Round-off sets in at a fraction of the forces' scale, the largest first residual of the
    # run, not of each solve's own: a predictor that starts a load step close to its solution
    # begins with a residual orders of magnitude below the loads.
    scale = max((res[0] for res in solves), default=0.0)
    for k, res in enumerate(solves):
        iterations = len(res) - 1
        # The order p of r_(k+1) ~ r_k^p over the last iterations above the round-off floor.
        floor = args.floor * scale
        useful = [v for v in res if v > floor]
        orders = [math.log(useful[j + 1] / useful[j]) / math.log(useful[j] / useful[j - 1])
                  for j in range(1, len(useful) - 1) if useful[j] != useful[j - 1]]
        last = orders[-1] if orders else float("nan")
        print("solve %d: %d iterations, |R| %s, last order %.2f"
              % (k + 1, iterations, " ".join("%.2e" % v for v in res), last))
        if iterations > args.max_iterations:
            failures.append("solve %d took %d iterations" % (k + 1, iterations))
        if orders and last < args.min_order:
            failures.append("solve %d converged with order %.2f < %g" % (k + 1, last, args.min_order))
        if args.ratio_bound:
            first = max(1, len(useful) - 1 - args.last) if args.last else 1
            ratios = [useful[j + 1] / useful[j] ** 2 for j in range(first, len(useful) - 1)]
            if args.last:
                print("  r_(k+1)/r_k^2 over the last pairs: %s"
                      % " ".join("%.2e" % v for v in ratios))
            for j, ratio in enumerate(ratios, start=first):
                if ratio > args.ratio_bound:
                    failures.append("solve %d: r_(k+1)/r_k^2 = %.2e at iteration %d" % (k + 1, ratio, j + 1))
    if not solves:
        failures.append("no Newton iterations in the log")
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def same(args):
    """Two decks must give the same particle table."""
    tables = []
    other = args.other or args.deck
    for deck, extra, log, unset in ((args.deck, args.set, args.expect_log, []),
                                    (other, args.set + args.other_set, args.other_expect_log,
                                     args.other_unset)):
        out = tempfile.mkdtemp(prefix="impm-same-", dir=".")
        run_deck = without_parameters(deck, unset, os.path.join(out, os.path.basename(deck)))
        r = run_impm(args, run_deck, out, ["Solver/Print Iterations=false"] + extra, np=args.np)
        if r.returncode != 0:
            print(r.stdout, r.stderr)
            sys.exit("impm failed on " + deck)
        if log and not re.search(log, r.stdout):
            print(r.stdout)
            sys.exit("the log of %s %s does not match %r" % (deck, " ".join(extra), log))
        tables.append(read_csv(os.path.join(out, stem(deck) + "_particles.csv")))
        shutil.rmtree(out)
    worst = 0.0
    for c in args.columns:
        a = [float(row[c]) for row in tables[0]]
        b = [float(row[c]) for row in tables[1]]
        scale = max(max(abs(v) for v in a), 1e-300)
        worst = max(worst, max(abs(x - y) for x, y in zip(a, b)) / scale)
    print("largest relative difference %.3e over columns %s" % (worst, ", ".join(args.columns)))
    sys.exit(1 if worst > args.rtol else 0)


def without_parameters(deck, paths, out_path):
    """deck itself, or with paths ("List/Sub/Name") removed, a copy written to out_path (for
    a run whose other settings make them unknown: a box's corners when it becomes a polygon)."""
    if not paths:
        return deck
    import xml.etree.ElementTree as ET
    tree = ET.parse(deck)
    for path in paths:
        node, names = tree.getroot(), path.split("/")
        for name in names[:-1]:
            node = next(c for c in node if c.get("name") == name)
        node.remove(next(c for c in node if c.get("name") == names[-1]))
    tree.write(out_path)
    return out_path


def slab_deck(deck, out_path):
    """Writes the 3-D slab of a 2-D deck: one cell thick along z (as thick as a cell is wide),
    rectangles become boxes and disks cylinders through the slab, Dirichlet boxes span it,
    and rollers on the back and front faces hold u_z = 0.  Plane strain is then the slab's
    exact state, so every field must equal the 2-D run's."""
    import xml.etree.ElementTree as ET
    tree = ET.parse(deck)
    root = tree.getroot()
    sub = lambda node, name: next(c for c in node if c.get("name") == name)
    numbers = lambda e: [v.strip() for v in e.get("value").strip("{} ").split(",")]
    array = lambda e, values: e.set("value", "{" + ", ".join(values) + "}")
    grid = sub(root, "Grid")
    cells, length = sub(grid, "Cells"), sub(grid, "Length")
    thickness = float(numbers(length)[0]) / float(numbers(cells)[0])
    array(cells, numbers(cells) + ["1"])
    array(length, numbers(length) + [repr(thickness)])
    for e in grid:
        if e.get("name") == "Origin" and numbers(e) != [""]:
            array(e, numbers(e) + ["0"])
    for body in sub(root, "Bodies"):
        shape = sub(body, "Shape")
        if shape.get("value") == "rectangle":
            shape.set("value", "box")
            array(sub(body, "Lower Corner"), numbers(sub(body, "Lower Corner")) + ["0"])
            array(sub(body, "Upper Corner"), numbers(sub(body, "Upper Corner")) + [repr(thickness)])
        elif shape.get("value") == "disk":
            shape.set("value", "cylinder")
            array(sub(body, "Center"), numbers(sub(body, "Center")) + [repr(thickness / 2)])
            ET.SubElement(body, "Parameter", name="Length", type="double", value=repr(thickness))
        else:
            sys.exit("slab: no 3-D form of shape %s" % shape.get("value"))
    conditions = next((c for c in root if c.get("name") == "Boundary Conditions"), None)
    if conditions is None:
        conditions = ET.SubElement(root, "ParameterList", name="Boundary Conditions")
    for bc in conditions:
        kind = sub(bc, "Type").get("value")
        if kind != "Dirichlet":
            sys.exit("slab: no 3-D form of a %s condition" % kind)
        for e in bc:
            if e.get("name") == "Box":
                array(e, numbers(e) + ["0", repr(thickness)])
    for face in ("back", "front"):
        bc = ET.SubElement(conditions, "ParameterList", name="slab " + face)
        for name, value in (("Type", "Dirichlet"), ("Face", face), ("Component", "z")):
            ET.SubElement(bc, "Parameter", name=name, type="string", value=value)
    for v in root:
        if v.get("name") == "Verification" and any(e.get("name") == "Exact Displacement x"
                                                   for e in v):
            ET.SubElement(v, "Parameter", name="Exact Displacement z", type="string", value="0")
    tree.write(out_path)


def slab(args):
    """The 2-D deck and its 3-D slab (slab_deck) must give the same particle fields: each
    2-D particle has n copies through the slab's thickness (n particles per cell and
    direction), whose columns must equal its own to --rtol (relative to 1 for F and J, to the
    largest stress for stresses, to the largest displacement for displacements)."""
    out = tempfile.mkdtemp(prefix="impm-slab-", dir=".")
    three = os.path.join(out, stem(args.deck) + "_slab.xml")
    slab_deck(args.deck, three)
    tables = []
    for deck in (args.deck, three):
        run = os.path.join(out, stem(deck))
        r = run_impm(args, deck, run, ["Solver/Print Iterations=false"] + args.set, np=args.np)
        if r.returncode != 0:
            print(r.stdout, r.stderr)
            sys.exit("impm failed on " + deck)
        tables.append(read_csv(os.path.join(run, stem(deck) + "_particles.csv")))
    shutil.rmtree(out)
    two, slab_rows = tables
    key = lambda row: (round(float(row["X"]), 9), round(float(row["Y"]), 9))
    plane = {key(row): row for row in two}
    copies = {}
    for row in slab_rows:
        copies.setdefault(key(row), []).append(row)
    failures = []
    if set(copies) != set(plane):
        failures.append("the slab's particles are not the 2-D particles' copies through z")
    counts = {len(v) for v in copies.values()}
    print("%d 2-D particles, %d in the slab (%s per 2-D particle)"
          % (len(two), len(slab_rows), ", ".join(map(str, sorted(counts)))))
    worst = {}
    # Scales as in uniform: 1 for F and J, the largest of all the stresses (or displacements)
    # for a stress (a displacement), so that a component that is zero compares at round-off.
    largest = lambda prefix: max([abs(float(r[c])) for c in args.columns if c.startswith(prefix)
                                  for r in two] + [1e-300])
    for c in args.columns:
        scale = (1.0 if c[0] in "FJ" else largest("stress") if c.startswith("stress")
                 else largest("u_") if c.startswith("u_")
                 else max(max(abs(float(r[c])) for r in two), 1e-300))
        worst[c] = max(abs(float(r3[c]) - float(plane[k][c])) / scale
                       for k, rows in copies.items() if k in plane for r3 in rows)
        print("%-10s largest relative difference %.2e" % (c, worst[c]))
        if worst[c] > args.rtol:
            failures.append("%s differs by %.2e (allowed %g)" % (c, worst[c], args.rtol))
    for z in ("u_z",):
        largest = max(abs(float(r[z])) for r in slab_rows)
        print("%-10s largest %.2e" % (z, largest))
        if largest > args.rtol:
            failures.append("the slab moves along z (%s up to %.2e)" % (z, largest))
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)


def iterations(args):
    """Mean Krylov iterations per Newton iteration, one run per --size (a --set value), must
    stay within --ratio of each other (a preconditioner whose cost per unknown is flat), or
    with --first-at-most, the first must be at most that fraction of the last."""
    means = []
    for size in args.size:
        out = tempfile.mkdtemp(prefix="impm-iterations-", dir=".")
        r = run_impm(args, args.deck, out, ["Solver/Print Iterations=false"] + args.set + size,
                     np=args.np)
        if r.returncode != 0:
            print(r.stdout, r.stderr)
            sys.exit("impm failed on " + args.deck)
        rows = [row for row in read_csv(os.path.join(out, stem(args.deck) + "_history.csv"))
                if int(float(row["step"])) > 0]
        shutil.rmtree(out)
        newton = sum(float(row["newton_iterations"]) for row in rows)
        linear = sum(float(row["linear_iterations"]) for row in rows)
        means.append(linear / newton)
        print("%s: %.2f Krylov iterations per Newton iteration" % (" ".join(size), means[-1]))
    if args.first_at_most is not None:
        fraction = means[0] / means[-1]
        print("first / last = %.2f (allowed %.2f)" % (fraction, args.first_at_most))
        sys.exit(1 if fraction > args.first_at_most else 0)
    ratio = max(means) / min(means)
    print("largest / smallest = %.2f (allowed %.2f)" % (ratio, args.ratio))
    sys.exit(1 if ratio >= args.ratio else 0)


def docs(args):
    """Every parameter of --list-parameters is in the guide, and the guide names no other."""
    r = subprocess.run([args.impm, "--list-parameters"], capture_output=True, text=True)
    listed = set()
    for line in r.stdout.splitlines():
        if line and not line.startswith(" "):
            listed.add(line.split("  (")[0])
    guide = open(args.guide).read()
    documented = set(re.findall(r"`((?:[A-Z][A-Za-z ]*/)+[^`]+)`", guide))
    documented = {d for d in documented if d.split("/")[0] in {p.split("/")[0] for p in listed}}
    missing = sorted(listed - documented)
    stale = sorted(documented - listed)
    for m in missing:
        print("FAIL: not in %s: %s" % (args.guide, m))
    for s in stale:
        print("FAIL: %s documents %s, which impm does not have" % (args.guide, s))
    print("%d parameters listed, %d documented" % (len(listed), len(documented)))
    sys.exit(1 if missing or stale else 0)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", required=True, help="the impm executable")
    p.add_argument("--mpiexec", default="", help="MPI launcher up to the process count flag")
    sub = p.add_subparsers(dest="check", required=True)

    c = sub.add_parser("convergence")
    c.add_argument("--deck", required=True)
    c.add_argument("--method", required=True)
    c.add_argument("--cells", type=int, nargs="+", required=True)
    c.add_argument("--rate", type=float, nargs=2, metavar=("MIN", "MAX"),
                   help="range of every observed rate")
    c.add_argument("--exact", type=float,
                   help="instead of rates: the RMS error must stay below this at every size")
    c.add_argument("--max-error", type=float, nargs="+", help="largest RMS error at each size")
    c.add_argument("--min-error", type=float, help="smallest RMS error expected (inexact methods)")
    c.add_argument("--reactions", type=float, nargs=4, metavar=("F0", "FL", "TOL", "ORDER"),
                   help="exact F0 and FL, the allowed error at the coarsest grid, and the "
                        "order at which that bound shrinks (0: fixed)")
    c.add_argument("--time-step", type=float,
                   help="Time Step at the first size, scaled with the cell size")
    c.add_argument("--energy-drift", type=float,
                   help="largest relative change of the total energy at any size")
    c.add_argument("--energy-balance", type=float,
                   help="largest |energy_balance| over the largest external work, every step")
    c.add_argument("--energy-loss", type=float,
                   help="the run must lose at least this fraction of its energy (non-conserving)")
    c.add_argument("--np", type=int, default=1)
    c.add_argument("--set", action="append", default=[])
    c.add_argument("--grid", default="{%d}", help="Grid/Cells value, %%d the size (2-D: {1,%%d})")
    c.add_argument("--field", nargs=3, metavar=("COLUMN", "EXACT", "SCALE"),
                   help="also measure the RMS error of a particle column against a Python "
                        "expression of X, Y (math.*), relative to SCALE")
    c.add_argument("--field-rate", type=float, nargs=2, metavar=("MIN", "MAX"))
    c.add_argument("--field-max-error", type=float, nargs="+")

    u = sub.add_parser("uniform")
    u.add_argument("--deck", required=True)
    u.add_argument("--columns", nargs="+", required=True)
    u.add_argument("--rtol", type=float, default=1e-12)
    u.add_argument("--expect", nargs=2, action="append", default=[], metavar=("COLUMN", "VALUE"))
    u.add_argument("--reaction", nargs=2, action="append", default=[], metavar=("COLUMN", "WIDTH"),
                   help="the history column of a support on a y face of reference width WIDTH "
                        "must equal sigma_yy F_xx WIDTH at the last step")
    u.add_argument("--total-volume", type=float,
                   help="the particle volumes (the volume column) must sum to this")
    u.add_argument("--np", type=int, default=1)
    u.add_argument("--set", action="append", default=[])

    t = sub.add_parser("translation")
    t.add_argument("--deck", required=True)
    t.add_argument("--velocity", type=float, nargs=2, required=True)
    t.add_argument("--atol", type=float, default=1e-12)
    t.add_argument("--corners", action="store_true", help="the particles must carry corners")
    t.add_argument("--np", type=int, default=1)
    t.add_argument("--set", action="append", default=[])

    e = sub.add_parser("exclusive")
    e.add_argument("--deck", required=True)

    x = sub.add_parser("extreme")
    x.add_argument("--deck", required=True)
    x.add_argument("--column", required=True)
    x.add_argument("--stat", choices=["max", "min"], required=True)
    x.add_argument("--min", type=float, default=-float("inf"))
    x.add_argument("--max", type=float, default=float("inf"))
    x.add_argument("--np", type=int, default=1)
    x.add_argument("--set", action="append", default=[])

    h = sub.add_parser("history")
    h.add_argument("--deck", required=True)
    h.add_argument("--column", required=True)
    h.add_argument("--min", type=float, default=-float("inf"))
    h.add_argument("--max", type=float, default=float("inf"))
    h.add_argument("--last", action="store_true", help="judge the last row only")
    h.add_argument("--np", type=int, default=1)
    h.add_argument("--set", action="append", default=[])

    he = sub.add_parser("history-every")
    he.add_argument("--deck", required=True)
    he.add_argument("--every", type=int, required=True)
    he.add_argument("--np", type=int, default=1)
    he.add_argument("--set", action="append", default=[])

    e = sub.add_parser("energy")
    e.add_argument("--deck", required=True)
    e.add_argument("--tolerance", type=float, required=True)
    e.add_argument("--np", type=int, default=1)
    e.add_argument("--set", action="append", default=[])

    w = sub.add_parser("unloading")
    w.add_argument("--deck", required=True)
    w.add_argument("--peak-set", action="append", default=[], help="--set values of the peak run")
    w.add_argument("--modulus", type=float, required=True)
    w.add_argument("--plastic", default="equivalent_plastic_strain")
    w.add_argument("--rtol", type=float, default=1e-9)

    r = sub.add_parser("ranks")
    r.add_argument("--deck", required=True)
    r.add_argument("--np", type=int, nargs="+", required=True)
    r.add_argument("--rtol", type=float, default=1e-10)
    r.add_argument("--atol", type=float, default=0.0,
                   help="a column whose values all stay below this is round-off (a zero "
                        "shear, say) and is compared absolutely")
    r.add_argument("--expect-log", help="a regular expression the log of every run on more "
                   "than one rank must match (the runs print every step)")
    r.add_argument("--conserved", nargs="+", default=[],
                   help="history columns that must stay constant to 1e-13 relative")
    r.add_argument("--linear-iterations-within", type=int,
                   help="every step's Krylov iterations on more ranks must be within this of "
                        "the first run's (a preconditioner that is exact on any rank count)")
    r.add_argument("--set", action="append", default=[])

    f = sub.add_parser("fails")
    f.add_argument("--deck", required=True)
    f.add_argument("--exit", type=int, default=1)
    f.add_argument("--np", type=int, default=1)
    f.add_argument("--set", action="append", default=[])
    f.add_argument("--outputs-remain", action="store_true",
                   help="a numerical failure: the outputs of the steps done must remain readable")
    f.add_argument("--option", action="append", default=[],
                   help="a command-line option for impm (after --output-dir)")
    f.add_argument("--steps-done", type=int, default=1,
                   help="with --outputs-remain: the steps done before the failure, at least")
    f.add_argument("--same-error-with", action="append", default=[],
                   help="a --set under which the run must end with the same impm: line")

    n = sub.add_parser("newton")
    n.add_argument("--deck", required=True)
    n.add_argument("--max-iterations", type=int, default=20)
    n.add_argument("--min-order", type=float, default=1.0)
    n.add_argument("--ratio-bound", type=float, help="bound of r_(k+1) / r_k^2 (quadratic)")
    n.add_argument("--floor", type=float, default=1e-12,
                   help="residuals below this times the first are round-off")
    n.add_argument("--last", type=int, default=0,
                   help="bound the ratio over the last LAST pairs above the floor only (once "
                        "the plastic zone has settled); 0: every pair after the first")
    n.add_argument("--np", type=int, default=1)
    n.add_argument("--set", action="append", default=[])

    s = sub.add_parser("same")
    s.add_argument("--deck", required=True)
    s.add_argument("--other", help="the second deck (default: --deck, with --other-set)")
    s.add_argument("--other-set", action="append", default=[],
                   help="--set values of the second run only")
    s.add_argument("--expect-log", help="a regular expression the first run's log must match")
    s.add_argument("--other-expect-log", help="the same for the second run")
    s.add_argument("--other-unset", action="append", default=[],
                   help="a parameter (List/Sub/Name) of the deck the second run leaves out")
    s.add_argument("--np", type=int, default=1)
    s.add_argument("--columns", nargs="+", default=["u", "strain", "stress"])
    s.add_argument("--rtol", type=float, default=1e-8)
    s.add_argument("--set", action="append", default=[])

    sl = sub.add_parser("slab")
    sl.add_argument("--deck", required=True)
    sl.add_argument("--np", type=int, default=1)
    sl.add_argument("--columns", nargs="+",
                    default=["u_x", "u_y", "stress_xx", "stress_yy", "stress_xy", "stress_zz",
                             "J", "F_xx", "F_xy", "F_yx", "F_yy"])
    sl.add_argument("--rtol", type=float, default=1e-9)
    sl.add_argument("--set", action="append", default=[],
                    help="Path=value for both runs (not the grid or the bodies' geometry, "
                    "which the slab changes)")

    it = sub.add_parser("iterations")
    it.add_argument("--deck", required=True)
    it.add_argument("--size", action="append", nargs="+", required=True,
                    help="the --set values of one run (repeat for each size)")
    it.add_argument("--ratio", type=float, default=2.0)
    it.add_argument("--first-at-most", type=float,
                    help="instead of --ratio: the first run's mean must be at most this times "
                    "the last run's (a setting that must save iterations against another)")
    it.add_argument("--np", type=int, default=1)
    it.add_argument("--set", action="append", default=[])

    d = sub.add_parser("docs")
    d.add_argument("--guide", required=True)

    args = p.parse_args()
    {"convergence": convergence, "ranks": ranks, "fails": fails, "docs": docs, "newton": newton,
     "same": same, "slab": slab, "uniform": uniform, "translation": translation,
     "history": history, "extreme": extreme, "exclusive": exclusive,
     "history-every": history_every,
     "unloading": unloading, "energy": energy, "iterations": iterations}[args.check](args)


if __name__ == "__main__":
    main()
