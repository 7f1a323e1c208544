#!/usr/bin/env python3
"""Deck and file fuzzer: impm must never crash, hang, leak a library's backtrace or leave a
half-written output directory, whatever it is given.

Every deck of input/ is shortened (two load steps, or three time steps) and then mutated:
a parameter or sublist deleted, duplicated or renamed by one letter; a value replaced by the
wrong type, an empty string, NaN, inf, -0, +-1e308, a huge integer, a 10 kB string, a formula
with a syntax error, a division by zero, an unknown variable, or a formula that is NaN at one
particle only; an array made longer or shorter; a sublist put where a value belongs and the
reverse; the file truncated at a random byte, or replaced by random bytes or by a directory;
and each value mutation also as a --set override.  The other files impm reads are mutated as
well: checkpoints (truncated, bit-flipped, a dimension or a count changed), images (truncated,
bit-flipped, other dimensions in the header) and Exodus meshes (truncated, bit-flipped,
connectivity or counts that do not match the data).

Each mutant runs under a time limit (and a memory limit), on 1 rank or sometimes 2; at the
limit it gets SIGUSR1, and a run that is alive stops cleanly (a valid mutant may ask for a
long run), while one that is not is a hang.  The only acceptable outcomes are
  (a) exit status 0 (or 4, a failed verification check of the mutated problem) with a
      complete output directory: the history's rows all complete, the Exodus files readable;
  (b) a non-zero exit status with exactly one line "impm: error: <file>: ..." naming a file
      impm was given (the deck, a checkpoint, an image, a mesh, the output directory) and no
      output file at all, or one line "impm: numerical failure: ..." with the outputs of the
      steps done readable as in (a).
Anything else -- a signal (segmentation fault, abort, std::terminate), a hang, a line that is
not impm's (a Teuchos or muparser backtrace, "terminate called"), a missing or second error
line, output files after an input error, a torn history -- is a failure: it is printed, and
the mutant is saved (deck, files, command) under --keep for reproduction.

  fuzz.py --impm build/drivers/impm --count 300 --seed 1        a fixed sample (ctest)
  fuzz.py --impm build/drivers/impm --minutes 30 --seed 7       a campaign

Only the Python standard library and netCDF's ncdump and ncgen are used.
"""

import argparse
import concurrent.futures
import copy
import json
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# Values put where another was.
NUMBERS = ["nan", "NaN", "inf", "-inf", "-0", "0", "1e308", "-1e308", "1e-308", "-1",
           "99999999999999999999999", "2147483648", "-2147483649", "1.5", "0x10", "1e", "--1"]
FORMULAS = ["sin(", "1/0", "0/0", "foo*x", "x +* 2", "X > 0.5 ? sqrt(-1) : 1",
            "log(-1)", "1e308*1e308", "((((x", "x^x^x^x^x", "t > 0 ? 0/0 : 1", ""]
STRINGS = ["", " ", "x" * 10240, "\u00e9\u00e8", "../../etc/passwd", "none", "\t"]
TYPES = ["int", "double", "string", "bool", "Array(int)", "Array(double)", "Array(string)",
         "float", "unknown"]


def shorten(root):
    """Few steps, so that a valid mutant ends in a second or two."""
    ti = find_list(root, "Time Integration")
    if ti is None:
        return
    values = {p.get("name"): p for p in ti.findall("Parameter")}
    kind = values.get("Type").get("value") if "Type" in values else "static"
    if kind == "static":
        set_parameter(ti, "Load Steps", "int", "2")
    elif "Time Step" in values:
        dt = float(values["Time Step"].get("value"))
        set_parameter(ti, "Final Time", "double", repr(3 * dt))


def find_list(root, name):
    for child in root.findall("ParameterList"):
        if child.get("name") == name:
            return child
    return None


def set_parameter(plist, name, type_, value):
    for p in plist.findall("Parameter"):
        if p.get("name") == name:
            p.set("value", value)
            return
    ET.SubElement(plist, "Parameter", {"name": name, "type": type_, "value": value})


def elements(root):
    """(element, parent, path) of every Parameter and ParameterList below the root."""
    out = []

    def walk(node, path):
        for child in list(node):
            if child.tag not in ("Parameter", "ParameterList"):
                continue
            p = path + [child.get("name", "")]
            out.append((child, node, p))
            if child.tag == "ParameterList":
                walk(child, p)
    walk(root, [])
    return out


def one_letter(rng, name):
    if not name:
        return "x"
    k = rng.randrange(len(name))
    op = rng.choice(["delete", "insert", "replace"])
    letter = rng.choice("abcdefghijklmnopqrstuvwxyz ")
    if op == "delete":
        return name[:k] + name[k + 1:]
    if op == "insert":
        return name[:k] + letter + name[k:]
    return name[:k] + letter + name[k + 1:]


def bad_value(rng, param):
    type_ = param.get("type", "string")
    value = param.get("value", "")
    if type_.startswith("Array"):
        items = value.strip("{} ").split(",") if value.strip("{} ") else []
        choice = rng.randrange(4)
        if choice == 0 and items:
            return "{" + ",".join(items[:-1]) + "}"
        if choice == 1:
            return "{" + ",".join(items + items[-1:] if items else ["1"]) + "}"
        if choice == 2:
            return "{" + ",".join(rng.choice(NUMBERS) for _ in items or [0]) + "}"
        return rng.choice(["{", "}", "1,2", "{1,,2}", "{" + "1," * 5000 + "1}"])
    if type_ in ("double", "int"):
        return rng.choice(NUMBERS + STRINGS[:2] + ["true"])
    if type_ == "bool":
        return rng.choice(["maybe", "", "2", "TRUE", "yes"])
    # Strings: formulas where they look like one, otherwise anything.
    return rng.choice(FORMULAS + STRINGS + NUMBERS[:3])


def mutate_tree(rng, root):
    """One structural or value mutation; returns (description, --set override or None)."""
    items = elements(root)
    params = [i for i in items if i[0].tag == "Parameter"]
    lists = [i for i in items if i[0].tag == "ParameterList"]
    kind = rng.choice(["delete", "duplicate", "rename", "value", "value", "value", "type",
                       "sublist_for_value", "value_for_sublist", "set", "trailing"])
    numeric = [i for i in params if i[0].get("type") in ("int", "double")]
    if kind == "trailing" and not numeric:
        kind = "value"
    if kind in ("value", "type", "set", "sublist_for_value") and not params:
        kind = "delete"
    if kind == "value_for_sublist" and not lists:
        kind = "rename"
    if kind == "delete":
        el, parent, path = rng.choice(items)
        parent.remove(el)
        return "deleted " + "/".join(path), None
    if kind == "duplicate":
        el, parent, path = rng.choice(items)
        parent.append(copy.deepcopy(el))
        return "duplicated " + "/".join(path), None
    if kind == "rename":
        el, parent, path = rng.choice(items)
        el.set("name", one_letter(rng, el.get("name", "")))
        return "renamed %s to %s" % ("/".join(path), el.get("name")), None
    if kind == "value":
        el, parent, path = rng.choice(params)
        el.set("value", bad_value(rng, el))
        return "%s = %r" % ("/".join(path), el.get("value")[:60]), None
    if kind == "trailing":  # a number with text after it: must be refused, not cut short
        el, parent, path = rng.choice(numeric)
        el.set("value", el.get("value", "1") + rng.choice(["x", "e", " 4", ",2", "..", "%"]))
        return "%s = %r (must be refused)" % ("/".join(path), el.get("value")), None
    if kind == "type":
        el, parent, path = rng.choice(params)
        el.set("type", rng.choice(TYPES))
        return "%s type %s" % ("/".join(path), el.get("type")), None
    if kind == "sublist_for_value":
        el, parent, path = rng.choice(params)
        index = list(parent).index(el)
        parent.remove(el)
        sub = ET.Element("ParameterList", {"name": el.get("name", "")})
        ET.SubElement(sub, "Parameter", {"name": "x", "type": "double", "value": "1"})
        parent.insert(index, sub)
        return "sublist in place of " + "/".join(path), None
    if kind == "value_for_sublist":
        el, parent, path = rng.choice(lists)
        index = list(parent).index(el)
        parent.remove(el)
        parent.insert(index, ET.Element("Parameter", {"name": el.get("name", ""),
                                                      "type": "string", "value": "1"}))
        return "value in place of " + "/".join(path), None
    # --set: the deck stays, the override carries the bad value.
    el, parent, path = rng.choice(params)
    value = bad_value(rng, el)
    if rng.random() < 0.2:
        path = path[:-1] + [one_letter(rng, path[-1])]
    return "--set %s=%r" % ("/".join(path), value[:60]), "/".join(path) + "=" + value


class Corpus:
    """The shortened decks and the files they read, in a work directory that mirrors input/."""

    def __init__(self, work, inputs, impm):
        self.work = work
        self.dir = os.path.join(work, "input")
        os.makedirs(self.dir)
        for sub in ("images", "meshes"):
            if os.path.isdir(os.path.join(inputs, sub)):
                shutil.copytree(os.path.join(inputs, sub), os.path.join(self.dir, sub))
        self.decks = {}
        for name in sorted(os.listdir(inputs)):
            if not name.endswith(".xml"):
                continue
            tree = ET.parse(os.path.join(inputs, name))
            shorten(tree.getroot())
            self.decks[name] = tree
            tree.write(os.path.join(self.dir, name))
        self.images = sorted(os.path.join("images", f) for f in os.listdir(os.path.join(self.dir, "images"))) \
            if os.path.isdir(os.path.join(self.dir, "images")) else []
        self.meshes = sorted(os.path.join("meshes", f) for f in os.listdir(os.path.join(self.dir, "meshes"))) \
            if os.path.isdir(os.path.join(self.dir, "meshes")) else []
        self.checkpoints = self.make_checkpoints(impm)

    def make_checkpoints(self, impm):
        """A checkpoint of a 1-D and of a 2-D deck, to mutate."""
        out = {}
        for deck in ("bar_vibration.xml", "colliding_disks.xml"):
            if deck not in self.decks:
                continue
            d = os.path.join(self.work, "checkpoint-" + deck[:-4])
            r = subprocess.run([impm, "--quiet", "--output-dir", d, "--set",
                                "Output/Checkpoint Every=1", os.path.join(self.dir, deck)],
                               capture_output=True, text=True)
            found = sorted(f for f in os.listdir(d) if re.match(r".*_checkpoint_\d+\.nc$", f)) \
                if os.path.isdir(d) else []
            if r.returncode == 0 and found:
                out[deck] = os.path.join(d, found[0])
        return out


def mutate_bytes(rng, data):
    choice = rng.randrange(3)
    if choice == 0 and data:
        return data[:rng.randrange(len(data))], "truncated"
    if choice == 1 and data:
        b = bytearray(data)
        for _ in range(rng.randint(1, 8)):
            b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
        return bytes(b), "bit-flipped"
    return os.urandom(rng.randint(0, 4096)), "random bytes"


def mutate_netcdf(rng, path, out):
    """Changes a number of the file's text form (a dimension, a count, a connectivity entry,
    a value) and writes it back with ncgen: counts that do not match the data."""
    text = subprocess.run(["ncdump", path], capture_output=True, text=True).stdout
    numbers = list(re.finditer(r"(?<![\w.])\d+(?![\w.])", text))
    if not numbers:
        return False
    m = rng.choice(numbers)
    value = rng.choice(["0", "1", "2", "3", "7", "99999", str(int(m.group()) + 1),
                        str(max(0, int(m.group()) - 1))])
    text = text[:m.start()] + value + text[m.end():]
    cdl = out + ".cdl"
    with open(cdl, "w") as f:
        f.write(text)
    kind = subprocess.run(["ncdump", "-k", path], capture_output=True, text=True).stdout.strip()
    r = subprocess.run(["ncgen", "-k", kind or "nc4", "-o", out, cdl], capture_output=True)
    os.remove(cdl)
    return r.returncode == 0


class Mutant:
    def __init__(self, number, description, deck, argv, np, files):
        self.number, self.description, self.deck, self.argv = number, description, deck, argv
        self.np, self.files = np, files  # files: the paths impm may name in an error


def make_mutant(rng, corpus, number, root_dir):
    """A directory with the mutated deck (and files) and the command line to run."""
    d = os.path.join(root_dir, "m%06d" % number)
    os.makedirs(d)
    for sub in ("images", "meshes"):
        src = os.path.join(corpus.dir, sub)
        if os.path.isdir(src):
            os.symlink(src, os.path.join(d, sub))
    name = rng.choice(sorted(corpus.decks))
    deck = os.path.join(d, name)
    sets, extra, files = [], [], [deck]
    what = rng.random()
    if what < 0.62:  # the deck's tree
        tree = copy.deepcopy(corpus.decks[name])
        description, override = mutate_tree(rng, tree.getroot())
        tree.write(deck)
        if override:
            sets.append(override)
    elif what < 0.72:  # the deck's bytes
        tree = corpus.decks[name]
        tree.write(deck)
        with open(deck, "rb") as f:
            data, how = mutate_bytes(rng, f.read())
        with open(deck, "wb") as f:
            f.write(data)
        description = how + " deck"
    elif what < 0.74:
        os.makedirs(deck)
        description = "the deck is a directory"
    elif what < 0.84 and corpus.checkpoints:  # a checkpoint to restart from
        name = rng.choice(sorted(corpus.checkpoints))
        deck = os.path.join(d, name)
        corpus.decks[name].write(deck)
        source = corpus.checkpoints[name]
        target = os.path.join(d, "restart.nc")
        if rng.random() < 0.6:
            with open(source, "rb") as f:
                data, how = mutate_bytes(rng, f.read())
            with open(target, "wb") as f:
                f.write(data)
        else:
            how = "counts changed in" if mutate_netcdf(rng, source, target) else "copied"
            if not os.path.exists(target):
                shutil.copy(source, target)
        extra += ["--restart", target]
        files = [deck, target]
        description = how + " checkpoint of " + name
    else:  # an image or a mesh of a deck that reads it
        users = {"images": ["cylinder_lame_image.xml", "porous_specimen.xml"],
                 "meshes": ["cylinder_lame_mesh.xml"]}
        sub = rng.choice([s for s in users if getattr(corpus, s)])
        name = rng.choice([n for n in users[sub] if n in corpus.decks])
        deck = os.path.join(d, name)
        corpus.decks[name].write(deck)
        os.remove(os.path.join(d, sub))
        os.makedirs(os.path.join(d, sub))
        for f in os.listdir(os.path.join(corpus.dir, sub)):
            shutil.copy(os.path.join(corpus.dir, sub, f), os.path.join(d, sub, f))
        victim = os.path.join(d, rng.choice(getattr(corpus, sub)))
        if sub == "meshes" and rng.random() < 0.5:
            how = "counts changed in" if mutate_netcdf(rng, victim, victim + ".new") else "kept"
            if os.path.exists(victim + ".new"):
                os.replace(victim + ".new", victim)
        elif sub == "images" and rng.random() < 0.4:
            with open(victim, "rb") as f:
                data = bytearray(f.read())
            if len(data) > 24:  # PNG IHDR width and height
                data[16 + rng.randrange(8)] = rng.randrange(256)
            with open(victim, "wb") as f:
                f.write(bytes(data))
            how = "other dimensions in"
        else:
            with open(victim, "rb") as f:
                data, how = mutate_bytes(rng, f.read())
            with open(victim, "wb") as f:
                f.write(data)
        files = [deck, victim]
        description = "%s %s" % (how, os.path.relpath(victim, d))
    out = os.path.join(d, "out")
    argv = ["--output-dir", out] + extra
    for s in sets:
        argv += ["--set", s]
    argv.append(deck)
    np = 2 if rng.random() < 0.2 else 1
    with open(os.path.join(d, "command.txt"), "w") as f:
        f.write(description + "\n")
    return Mutant(number, description, deck, argv, np, files + [out])


# Lines mpirun prints when a rank exits with a non-zero status: not impm's, but expected.
MPIRUN = re.compile(r"^(-{20,}|Primary job +terminated normally|a non-zero exit code|"
                    r"(mpirun|mpiexec) detected|the job to be terminated|the job has been aborted|"
                    r"\s+Process name:|\s+Exit code:|Per user-direction|$)")
USAGE = re.compile(r"^(usage: impm|\s+impm |\s*$|Runs the implicit|  --|Exit status|"
                   r"On SIGINT|how to continue|under mpirun|[0-9], |failure, |\s{20,})")


def history_complete(path):
    try:
        with open(path) as f:
            rows = [line.rstrip("\n").split(",") for line in f]
    except OSError:
        return "no history"
    if len(rows) < 2:
        return "the history has no row"
    width = len(rows[0])
    for k, r in enumerate(rows[1:], 1):
        if len(r) != width:
            return "history row %d has %d of %d columns" % (k, len(r), width)
        for v in r:
            try:
                float(v)
            except ValueError:
                return "history row %d holds %r" % (k, v[:20])
    return ""


def outputs_readable(out):
    """'' when every output file there is complete and readable, otherwise why not."""
    if not os.path.isdir(out):
        return "no output directory"
    names = os.listdir(out)
    problem = next((history_complete(os.path.join(out, n)) for n in names
                    if n.endswith("_history.csv")), "no history file")
    if problem:
        return problem
    for n in names:
        if n.endswith(".tmp"):
            return "a half-written file remains: " + n
        if n.endswith(".exo") or n.endswith(".nc"):
            r = subprocess.run(["ncdump", "-h", os.path.join(out, n)], capture_output=True)
            if r.returncode != 0:
                return n + " does not open"
    return ""


def judge(m, returncode, stdout, stderr, timed_out):
    """'' for an acceptable outcome, otherwise what is wrong."""
    if timed_out:
        return "hang: no end within the time limit"
    if returncode < 0 or returncode > 128:
        sig = -returncode if returncode < 0 else returncode - 128
        try:
            name = signal.Signals(sig).name
        except ValueError:
            name = str(sig)
        return "killed by " + name
    out = m.argv[m.argv.index("--output-dir") + 1]
    lines = stderr.splitlines()
    impm_lines = [l for l in lines if l.startswith("impm: error:") or
                  l.startswith("impm: numerical failure:")]
    foreign = [l for l in lines if not l.startswith("impm: ") and not MPIRUN.match(l)
               and not (returncode == 2 and USAGE.match(l))]
    if foreign:
        return "a line that is not impm's: %r" % foreign[0][:200]
    for marker in ("terminate called", "Throw number", "Traceback", "Segmentation", "Abort"):
        if marker in stdout or marker in stderr:
            return "%r in the output" % marker
    if returncode == 5 or "impm: stopped by SIGUSR1" in stderr:  # stopped at the time limit
        stopped = [l for l in lines if l.startswith("impm: stopped by SIGUSR1")]
        if len(stopped) != 1 or "; continue with: " not in stopped[0]:
            return "no clean stop at the time limit"
        return outputs_readable(out)
    if returncode in (0, 4):
        if "(must be refused)" in m.description:
            return "an invalid value was accepted"
        if impm_lines:
            return "exit status %d with an error line: %s" % (returncode, impm_lines[0][:200])
        return outputs_readable(out)
    if len(impm_lines) != 1:
        return "exit status %d with %d error lines" % (returncode, len(impm_lines))
    line = impm_lines[0]
    if line.startswith("impm: numerical failure:"):
        return "" if not os.path.exists(out) else outputs_readable(out)
    # A file it was given, or one the deck names (in the mutant's directory).
    home = os.path.dirname(m.deck) + "/"
    named = any(line.startswith("impm: error: %s: " % f) for f in m.files) or \
        line.startswith("impm: error: " + home) or \
        line.startswith("impm: error: ") and returncode == 2
    if not named:
        return "the error names no file it was given: %s" % line[:200]
    if os.path.exists(out) and (os.path.isfile(out) or os.listdir(out)):
        return "output files after an input error: %s" % (
            ", ".join(sorted(os.listdir(out))[:5]) if os.path.isdir(out) else out)
    return ""


def run_mutant(args, m):
    cmd = []
    if m.np > 1:
        cmd += shlex.split(args.mpiexec) + [str(m.np)]
    cmd += [args.impm, "--quiet"] + m.argv

    def limits():
        os.setsid()
        import resource
        memory = args.memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    began = time.time()
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         errors="replace", preexec_fn=limits)
    timed_out = False
    try:
        stdout, stderr = p.communicate(timeout=args.timeout)
    except subprocess.TimeoutExpired:
        # A valid mutant may ask for a long run (Final Time = 1e6): one that is alive stops
        # cleanly on SIGUSR1 (mpirun passes it on) and counts as a run; a hung one does not.
        os.killpg(p.pid, signal.SIGUSR1)
        try:
            stdout, stderr = p.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            timed_out = True
            os.killpg(p.pid, signal.SIGKILL)
            stdout, stderr = p.communicate()
    verdict = judge(m, p.returncode, stdout, stderr, timed_out)
    return verdict, p.returncode, time.time() - began, stdout, stderr, cmd


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--impm", default=os.path.join(ROOT, "build", "drivers", "impm"))
    p.add_argument("--mpiexec", default="mpirun --allow-run-as-root --oversubscribe "
                                        "--mca pml ob1 --mca btl self,vader -n")
    p.add_argument("--inputs", default=os.path.join(ROOT, "input"))
    p.add_argument("--count", type=int, help="this many mutants")
    p.add_argument("--minutes", type=float, help="mutants until this much time has passed")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    p.add_argument("--timeout", type=float, default=60.0, help="seconds per mutant")
    p.add_argument("--memory-mb", type=int, default=4096, help="address-space limit per process")
    p.add_argument("--keep", default="fuzz-failures", help="where failing mutants are saved")
    p.add_argument("--summary", help="write the counts as JSON here")
    args = p.parse_args()
    if not args.count and not args.minutes:
        p.error("give --count or --minutes")
    args.impm = os.path.abspath(args.impm)
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="impm-fuzz-")
    began = time.time()
    corpus = Corpus(work, os.path.abspath(args.inputs), args.impm)
    print("impm fuzz: seed %d, %d decks, %d images, %d meshes, %d checkpoints" % (
        args.seed, len(corpus.decks), len(corpus.images), len(corpus.meshes),
        len(corpus.checkpoints)), flush=True)
    counts = {"mutants": 0, "exit 0": 0, "exit 4": 0, "input error": 0, "numerical failure": 0,
              "command-line error": 0, "stopped at the time limit": 0, "failures": 0}
    failures = []
    number = 0

    def more():
        if args.count:
            return number < args.count
        return time.time() - began < 60 * args.minutes

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        pending = {}
        while more() or pending:
            while more() and len(pending) < 2 * args.jobs:
                m = make_mutant(rng, corpus, number, work)
                number += 1
                pending[pool.submit(run_mutant, args, m)] = m
            done, _ = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in done:
                m = pending.pop(f)
                verdict, rc, seconds, stdout, stderr, cmd = f.result()
                counts["mutants"] += 1
                if verdict:
                    counts["failures"] += 1
                    saved = os.path.join(args.keep, "m%06d" % m.number)
                    shutil.rmtree(saved, ignore_errors=True)
                    shutil.copytree(os.path.dirname(m.deck) if os.path.isfile(m.deck)
                                    else os.path.join(work, "m%06d" % m.number), saved,
                                    symlinks=True)
                    with open(os.path.join(saved, "command.txt"), "w") as out:
                        out.write("%s\n%s\nexit status %d\n--- stdout\n%s\n--- stderr\n%s\n" % (
                            m.description, " ".join(shlex.quote(c) for c in cmd), rc,
                            stdout[-4000:], stderr[-4000:]))
                    failures.append((m, verdict))
                    print("FAIL mutant %d (%s, np %d): %s\n     saved in %s" % (
                        m.number, m.description, m.np, verdict, saved), flush=True)
                elif "impm: stopped by SIGUSR1" in stderr:
                    counts["stopped at the time limit"] += 1
                elif rc in (0, 4):
                    counts["exit %d" % rc] += 1
                elif rc == 2:
                    counts["command-line error"] += 1
                elif "impm: numerical failure:" in stderr:
                    counts["numerical failure"] += 1
                else:
                    counts["input error"] += 1
                shutil.rmtree(os.path.join(work, "m%06d" % m.number), ignore_errors=True)
    shutil.rmtree(work, ignore_errors=True)
    elapsed = time.time() - began
    print("impm fuzz: %d mutants in %.0f s: %d ran (%d with a failed verification check, %d "
          "stopped cleanly at the time limit), %d input errors, %d numerical failures, %d "
          "command-line errors; %d failures" % (
              counts["mutants"], elapsed,
              counts["exit 0"] + counts["exit 4"] + counts["stopped at the time limit"],
              counts["exit 4"], counts["stopped at the time limit"], counts["input error"],
              counts["numerical failure"], counts["command-line error"], counts["failures"]))
    if args.summary:
        with open(args.summary, "w") as f:
            json.dump(dict(counts, seconds=round(elapsed), seed=args.seed), f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
