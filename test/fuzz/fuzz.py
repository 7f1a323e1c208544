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
connectivity or counts that do not match the data).  Further families (FAMILIES, --families):
  nox list              a Solver/NOX choice from NOX's own menu, a bogus one, or a bad number;
  checkpoint attribute  one attribute of a checkpoint changed (must be refused: every byte a
                        restart reads is checksummed);
  concurrent writers    the same run started twice on one output directory, the second a
                        random moment later (one must refuse, or the first have ended; the
                        directory holds one run's history, steps in order);
  restart change        a restart from an intact checkpoint with a mutated deck, sometimes
                        with --allow-physics-change;
  set path              a --set whose path names nothing (a misspelt parameter or list, a
                        path through a value, empty components, no '='): must be refused;
  deep nesting          a chain of 2 to 20,000 nested ParameterLists in the deck;
  not a file            the deck, checkpoint, image or mesh replaced by a FIFO, a directory,
                        a loop of links, a dangling link or a device: must be refused.

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
  fuzz.py ... --families "nox list,set path"                    a campaign over some families

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


def number_at(text, k):
    """The value of the number in text around position k (ncdump's form: 0.05, 20LL, 3ULL)."""
    begin, end = k, k
    while begin > 0 and (text[begin - 1].isdigit() or text[begin - 1] in ".eE+-"):
        begin -= 1
    while end < len(text) and (text[end].isdigit() or text[end] in ".eE+-"):
        end += 1
    try:
        return float(text[begin:end])
    except ValueError:
        return text[begin:end]


def change_attribute(rng, path):
    """Changes one character of one global attribute's value (not the format version) through
    the file's text form, written back with ncgen; the attribute's name, or None."""
    text = subprocess.run(["ncdump", "-p", "9,17", path], capture_output=True,
                          text=True).stdout
    begin = text.find("// global attributes:")
    starts = [m for m in re.finditer(r"^\t\t:(\w+) = ", text[begin:], re.M)
              if m.group(1) != "impm_checkpoint_version"] if begin >= 0 else []
    if not starts:
        return None
    m = rng.choice(starts)
    first = begin + m.end()
    last = text.index(" ;\n", first)
    strings = [k for k in range(first, last) if text[k].isalnum() and
               text[:k].count('"', first) % 2 == 1]
    digits = [k for k in range(first, last) if text[k].isdigit()]
    spots = strings if strings else digits
    if not spots:
        return None
    for _ in range(20):  # a digit past a double's precision leaves the value as it was
        k = rng.choice(spots)
        pool = "0123456789" if text[k].isdigit() else "abcdefghijklmnopqrstuvwxyz"
        changed = text[:k] + rng.choice(pool.replace(text[k].lower(), "")) + text[k + 1:]
        if spots is strings or number_at(text, k) != number_at(changed, k):
            break
    else:
        return None
    text = changed
    cdl = path + ".cdl"
    with open(cdl, "w") as f:
        f.write(text)
    kind = subprocess.run(["ncdump", "-k", path], capture_output=True, text=True).stdout.strip()
    r = subprocess.run(["ncgen", "-k", kind or "nc4", "-o", path + ".new", cdl],
                       capture_output=True)
    os.remove(cdl)
    if r.returncode != 0 or not os.path.exists(path + ".new"):
        return None
    os.replace(path + ".new", path)
    return m.group(1)


class Mutant:
    def __init__(self, number, family, description, deck, argv, np, files, partner_delay=None):
        self.number, self.family, self.description = number, family, description
        self.deck, self.argv, self.np, self.files = deck, argv, np, files
        # files: the paths impm may name in an error; partner_delay: a second, identical run
        # starts this many seconds after the first (concurrent writers).
        self.partner_delay = partner_delay


# The families of mutants and their weights in a campaign that draws from all of them.
FAMILIES = {"deck tree": 50, "deck bytes": 8, "deck directory": 1, "checkpoint": 8,
            "image or mesh": 10, "nox list": 5, "checkpoint attribute": 4,
            "concurrent writers": 3, "restart change": 4, "set path": 4, "deep nesting": 2,
            "not a file": 3}

# NOX's own menu (NOX 13.2), with values it does not know: impm serves some, refuses the
# others by name; none may crash it.
NOX_MENU = {
    "Nonlinear Solver": ["Line Search Based", "Trust Region Based", "Inexact Trust Region Based",
                         "Tensor Based", "Single Step", "Anderson Accelerated Fixed-Point",
                         "Pseudo-Transient", "Bogus", ""],
    "Direction/Method": ["Newton", "Steepest Descent", "NonlinearCG", "Broyden", "Tensor",
                         "Modified-Newton", "Quasi-Newton", "User Defined", "Bogus"],
    "Line Search/Method": ["Full Step", "Backtrack", "Polynomial", "More'-Thuente",
                           "NonlinearCG", "Safeguarded Step", "Tensor", "User Defined", "Bogus"],
    "Line Search/Polynomial/Interpolation Type": ["Quadratic", "Cubic", "Quadratic3", "Bogus"],
    "Line Search/Polynomial/Sufficient Decrease Condition": ["Armijo-Goldstein", "Ared/Pred",
                                                             "None", "Bogus"],
    "Line Search/Backtrack/Max Iters": NUMBERS,
    "Line Search/Backtrack/Minimum Step": NUMBERS,
    "Line Search/Full Step/Full Step": NUMBERS,
    "Direction/Newton/Forcing Term Method": ["Constant", "Type 1", "Type 2", "Bogus"],
    "Trust Region/Minimum Trust Region Radius": NUMBERS,
    "Printing/Output Information": ["0", "-1", "127", "x"],
}


def image_or_mesh_file(tree):
    """The first image or mesh file the deck names, relative to its directory, or None."""
    for el, _, _ in elements(tree.getroot()):
        if el.tag == "Parameter" and el.get("name") in ("Image File", "Mesh File"):
            return el.get("value")
    return None


def own_copy(d, corpus, sub):
    """The mutant's own copy of the corpus' images/ or meshes/ (to change one file)."""
    os.remove(os.path.join(d, sub))
    shutil.copytree(os.path.join(corpus.dir, sub), os.path.join(d, sub))


def deck_tree(rng, corpus, d, name):
    deck = os.path.join(d, name)
    tree = copy.deepcopy(corpus.decks[name])
    description, override = mutate_tree(rng, tree.getroot())
    tree.write(deck)
    return deck, description, [override] if override else [], [], [deck]


def deck_bytes(rng, corpus, d, name):
    deck = os.path.join(d, name)
    corpus.decks[name].write(deck)
    with open(deck, "rb") as f:
        data, how = mutate_bytes(rng, f.read())
    with open(deck, "wb") as f:
        f.write(data)
    return deck, how + " deck", [], [], [deck]


def deck_directory(rng, corpus, d, name):
    deck = os.path.join(d, name)
    os.makedirs(deck)
    return deck, "the deck is a directory", [], [], [deck]


def restart_of(corpus, d, name, target):
    """The deck of a checkpoint's run, and an intact copy of the checkpoint at target."""
    deck = os.path.join(d, name)
    corpus.decks[name].write(deck)
    shutil.copy(corpus.checkpoints[name], target)
    return deck


def checkpoint(rng, corpus, d, name):
    name = rng.choice(sorted(corpus.checkpoints))
    target = os.path.join(d, "restart.nc")
    deck = restart_of(corpus, d, name, target)
    if rng.random() < 0.6:
        with open(target, "rb") as f:
            data, how = mutate_bytes(rng, f.read())
        with open(target, "wb") as f:
            f.write(data)
    else:
        how = "counts changed in" if mutate_netcdf(rng, target, target + ".new") else "copied"
        if os.path.exists(target + ".new"):
            os.replace(target + ".new", target)
    return deck, how + " checkpoint of " + name, [], ["--restart", target], [deck, target]


def checkpoint_attribute(rng, corpus, d, name):
    name = rng.choice(sorted(corpus.checkpoints))
    target = os.path.join(d, "restart.nc")
    deck = restart_of(corpus, d, name, target)
    changed = change_attribute(rng, target)
    description = ("attribute %s changed in the checkpoint of %s (must be refused)"
                   % (changed, name)) if changed else "intact checkpoint of " + name
    return deck, description, [], ["--restart", target], [deck, target]


def restart_change(rng, corpus, d, name):
    name = rng.choice(sorted(corpus.checkpoints))
    target = os.path.join(d, "restart.nc")
    deck = restart_of(corpus, d, name, target)
    tree = copy.deepcopy(corpus.decks[name])
    description, override = mutate_tree(rng, tree.getroot())
    tree.write(deck)
    extra = ["--restart", target]
    if rng.random() < 0.3:
        extra.append("--allow-physics-change")
    return (deck, "restart of %s with %s%s" % (name, description, " (allowed)" if len(extra) > 2
                                                 else ""),
            [override] if override else [], extra, [deck, target])


def image_or_mesh(rng, corpus, d, name):
    users = {"images": ["cylinder_lame_image.xml", "porous_specimen.xml"],
             "meshes": ["cylinder_lame_mesh.xml"]}
    sub = rng.choice([s for s in users if getattr(corpus, s)])
    name = rng.choice([n for n in users[sub] if n in corpus.decks])
    deck = os.path.join(d, name)
    corpus.decks[name].write(deck)
    own_copy(d, corpus, sub)
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
    return deck, "%s %s" % (how, os.path.relpath(victim, d)), [], [], [deck, victim]


def nox_list(rng, corpus, d, name):
    deck = os.path.join(d, name)
    corpus.decks[name].write(deck)
    sets = []
    for _ in range(rng.randint(1, 3)):
        path = rng.choice(sorted(NOX_MENU))
        sets.append("Solver/NOX/%s=%s" % (path, rng.choice(NOX_MENU[path])))
    if rng.random() < 0.3:
        sets.append("Solver/Line Search=" + rng.choice(["Backtrack", "Full Step", "Polynomial"]))
    return deck, "--set " + "; ".join(sets), sets, [], [deck]


def set_path(rng, corpus, d, name):
    """A --set naming nothing the deck has or may have: refused."""
    deck = os.path.join(d, name)
    tree = corpus.decks[name]
    tree.write(deck)
    params = [(el, p) for el, _, p in elements(tree.getroot())
              if el.tag == "Parameter" and p[0] != "Solver"]
    el, path = rng.choice(params)
    names = [c.get("name") for c in tree.getroot().iter() if c.get("name")]
    kind = rng.randrange(6)
    if kind == 0:  # a misspelt parameter
        leaf = one_letter(rng, path[-1])
        while leaf in names:
            leaf += "x"
        text = "/".join(path[:-1] + [leaf]) + "=1"
    elif kind == 1 and len(path) > 1:  # a misspelt list
        k = rng.randrange(len(path) - 1)
        step = one_letter(rng, path[k])
        while step in names:
            step += "x"
        text = "/".join(path[:k] + [step] + path[k + 1:]) + "=1"
    elif kind == 2:  # through a value
        text = "/".join(path + ["x"]) + "=1"
    elif kind == 3:  # an empty component
        k = rng.randrange(len(path) + 1)
        text = "/".join(path[:k] + [""] + path[k:]) + "=" + el.get("value", "1")
    elif kind == 4:  # no value
        text = "/".join(path)
    else:  # a leading or trailing '/'
        text = rng.choice(["/", ""]) + "/".join(path) + rng.choice(["/", ""]) + "=1"
        if not text.startswith("/") and "/=" not in text:
            text = "/" + text
    return deck, "--set %r (must be refused)" % text, [text], [], [deck]


def deep_nesting(rng, corpus, d, name):
    """A chain of nested lists at a random place; the text is made by hand (ElementTree's
    writer recurses and cannot write 20,000 levels)."""
    deck = os.path.join(d, name)
    tree = copy.deepcopy(corpus.decks[name])
    lists = [el for el, _, _ in elements(tree.getroot()) if el.tag == "ParameterList"]
    where = rng.choice(lists + [tree.getroot()])
    ET.SubElement(where, "Parameter", {"name": "DEEP-HERE", "type": "int", "value": "1"})
    text = ET.tostring(tree.getroot(), encoding="unicode")
    depth = rng.choice([2, 20, 31, 32, 33, 100, 5000, 20000])
    chain = ('<ParameterList name="a">' * depth + '<Parameter name="b" type="int" value="1"/>' +
             "</ParameterList>" * depth)
    text = re.sub(r'<Parameter name="DEEP-HERE"[^>]*/>', chain, text)
    with open(deck, "w") as f:
        f.write(text)
    return deck, "%d nested lists (must be refused)" % depth, [], [], [deck]


def not_a_file(rng, corpus, d, name):
    """The deck, a checkpoint, an image or a mesh replaced by what is not a regular file."""
    target_kind = rng.choice(["deck", "checkpoint", "image or mesh"])
    deck = os.path.join(d, name)
    corpus.decks[name].write(deck)
    extra = []
    if target_kind == "checkpoint" and corpus.checkpoints:
        name = rng.choice(sorted(corpus.checkpoints))
        victim = os.path.join(d, "restart.nc")
        deck = restart_of(corpus, d, name, victim)
        extra = ["--restart", victim]
    elif target_kind == "image or mesh":
        name = rng.choice(["cylinder_lame_image.xml", "cylinder_lame_mesh.xml",
                           "porous_specimen.xml"])
        deck = os.path.join(d, name)
        corpus.decks[name].write(deck)
        relative = image_or_mesh_file(corpus.decks[name])
        own_copy(d, corpus, relative.split("/")[0])
        victim = os.path.join(d, relative)
    else:
        victim = deck
    if os.path.exists(victim):
        os.remove(victim)
    how = rng.choice(["fifo", "directory", "link loop", "dangling link", "/dev/zero",
                      "/dev/null"])
    if how == "fifo":
        os.mkfifo(victim)
    elif how == "directory":
        os.makedirs(victim)
    elif how == "link loop":
        os.symlink(victim + ".back", victim)
        os.symlink(victim, victim + ".back")
    elif how == "dangling link":
        os.symlink(victim + ".none", victim)
    else:
        os.symlink(how, victim)
    return (deck, "%s is a %s (must be refused)" % (os.path.relpath(victim, d), how), [], extra,
            [deck, victim])


def concurrent_writers(rng, corpus, d, name):
    deck = os.path.join(d, name)
    corpus.decks[name].write(deck)
    return deck, "the same run twice on one directory", [], [], [deck]


MAKERS = {"deck tree": deck_tree, "deck bytes": deck_bytes, "deck directory": deck_directory,
          "checkpoint": checkpoint, "image or mesh": image_or_mesh, "nox list": nox_list,
          "checkpoint attribute": checkpoint_attribute, "concurrent writers": concurrent_writers,
          "restart change": restart_change, "set path": set_path, "deep nesting": deep_nesting,
          "not a file": not_a_file}


def make_mutant(rng, corpus, number, root_dir, families):
    """A directory with the mutated deck (and files) and the command line to run."""
    d = os.path.join(root_dir, "m%06d" % number)
    os.makedirs(d)
    for sub in ("images", "meshes"):
        src = os.path.join(corpus.dir, sub)
        if os.path.isdir(src):
            os.symlink(src, os.path.join(d, sub))
    family = rng.choices(families, [FAMILIES[f] for f in families])[0]
    if not corpus.checkpoints and family in ("checkpoint", "checkpoint attribute",
                                             "restart change"):
        family = "deck tree"
    name = rng.choice(sorted(corpus.decks))
    deck, description, sets, extra, files = MAKERS[family](rng, corpus, d, name)
    out = os.path.join(d, "out")
    argv = ["--output-dir", out] + extra
    for s in sets:
        argv += ["--set", s]
    argv.append(deck)
    np = 2 if rng.random() < 0.2 else 1
    # The shortened runs take a fraction of a second: most pairs start close enough to meet.
    delay = rng.choice([0.0, rng.uniform(0.0, 0.3), rng.uniform(0.0, 1.5)]) \
        if family == "concurrent writers" else None
    with open(os.path.join(d, "command.txt"), "w") as f:
        f.write(description + "\n")
    return Mutant(number, family, description, deck, argv, np, files + [out], delay)


# Lines mpirun prints when a rank exits with a non-zero status: not impm's, but expected.
MPIRUN = re.compile(r"^(-{20,}|Primary job +terminated normally|a non-zero exit code|"
                    r"(mpirun|mpiexec) detected|the job to be terminated|the job has been aborted|"
                    r"\s+Process name:|\s+Exit code:|Per user-direction|$)")
USAGE = re.compile(r"^(usage: impm|\s+impm |\s+\[--|Run impm --help|\s*$|Runs the implicit|  --|Exit status|"
                   r"On SIGINT|how to continue|under mpirun|[0-9], |failure, |\s{20,})")


def history_complete(path):
    """'' when every row is complete and the steps increase (one run's rows, not two
    interleaved), otherwise why not.  A restart's notes are comment lines."""
    try:
        with open(path) as f:
            rows = [line.rstrip("\n").split(",") for line in f if not line.startswith("# ")]
    except OSError:
        return "no history"
    if len(rows) < 2:
        return "the history has no row"
    width = len(rows[0])
    step = -1.0
    for k, r in enumerate(rows[1:], 1):
        if len(r) != width:
            return "history row %d has %d of %d columns" % (k, len(r), width)
        for v in r:
            try:
                float(v)
            except ValueError:
                return "history row %d holds %r" % (k, v[:20])
        if float(r[0]) <= step:
            return "history row %d is step %s after step %g" % (k, r[0], step)
        step = float(r[0])
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
        if "no step to take, nothing written" in stdout and not os.path.exists(out):
            return ""  # a restart at or past its Final Time
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


def judge_concurrent(m, runs):
    """Two runs on one directory: each ends well or is refused for the other's lock, at least
    one ends well, and the directory holds one run's complete outputs."""
    out = m.argv[m.argv.index("--output-dir") + 1]
    finished = 0
    for k, (returncode, stdout, stderr, timed_out) in enumerate(runs):
        which = ("first", "second")[k]
        if timed_out:
            return "the %s run hangs" % which
        if returncode < 0 or returncode > 128:
            return "the %s run was killed (status %d)" % (which, returncode)
        lines = [l for l in stderr.splitlines() if l.startswith("impm: ")]
        if returncode in (0, 4, 5):
            finished += 1
        elif not (len(lines) == 1 and "is in use by another impm run" in lines[0]):
            return "the %s run exits %d: %s" % (which, returncode, stderr.strip()[:200])
    if not finished:
        return "neither run ended well"
    return outputs_readable(out)


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

    def start():
        return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                errors="replace", preexec_fn=limits)

    def finish(p, timeout):
        try:
            stdout, stderr = p.communicate(timeout=max(timeout, 1))
            return stdout, stderr, False
        except subprocess.TimeoutExpired:
            # A valid mutant may ask for a long run (Final Time = 1e6): one that is alive
            # stops cleanly on SIGUSR1 (mpirun passes it on) and counts as a run; a hung one
            # does not.
            os.killpg(p.pid, signal.SIGUSR1)
            try:
                stdout, stderr = p.communicate(timeout=30)
                return stdout, stderr, False
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                stdout, stderr = p.communicate()
                return stdout, stderr, True

    began = time.time()
    p = start()
    if m.partner_delay is not None:
        time.sleep(m.partner_delay)
        second = start()
        stdout, stderr, timed_out = finish(p, args.timeout - (time.time() - began))
        stdout2, stderr2, timed_out2 = finish(second, args.timeout - (time.time() - began))
        verdict = judge_concurrent(m, [(p.returncode, stdout, stderr, timed_out),
                                       (second.returncode, stdout2, stderr2, timed_out2)])
        return (verdict, max(p.returncode, second.returncode), time.time() - began,
                stdout + "\n--- second run\n" + stdout2, stderr + "\n--- second run\n" + stderr2,
                cmd)
    stdout, stderr, timed_out = finish(p, args.timeout)
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
    p.add_argument("--families", default=",".join(FAMILIES),
                   help="comma-separated families to draw from (default: all): " +
                   ", ".join(FAMILIES))
    args = p.parse_args()
    if not args.count and not args.minutes:
        p.error("give --count or --minutes")
    args.impm = os.path.abspath(args.impm)
    families = [f.strip() for f in args.families.split(",") if f.strip()]
    unknown = [f for f in families if f not in FAMILIES]
    if unknown or not families:
        p.error("unknown families %s; the families are %s" % (unknown, ", ".join(FAMILIES)))
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
    by_family = {}
    number = 0

    def more():
        if args.count:
            return number < args.count
        return time.time() - began < 60 * args.minutes

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        pending = {}
        while more() or pending:
            while more() and len(pending) < 2 * args.jobs:
                m = make_mutant(rng, corpus, number, work, families)
                number += 1
                pending[pool.submit(run_mutant, args, m)] = m
            done, _ = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in done:
                m = pending.pop(f)
                verdict, rc, seconds, stdout, stderr, cmd = f.result()
                counts["mutants"] += 1
                family = by_family.setdefault(m.family, {"mutants": 0, "failures": 0})
                family["mutants"] += 1
                family["failures"] += 1 if verdict else 0
                if m.partner_delay is not None and "is in use by another impm run" in stderr:
                    family["refused"] = family.get("refused", 0) + 1  # the runs overlapped
                if verdict:
                    counts["failures"] += 1
                    saved = os.path.join(args.keep, "m%06d" % m.number)
                    shutil.rmtree(saved, ignore_errors=True)
                    try:  # FIFOs and devices are not copied (shutil refuses them)
                        shutil.copytree(os.path.dirname(m.deck) if os.path.isfile(m.deck)
                                        else os.path.join(work, "m%06d" % m.number), saved,
                                        symlinks=True)
                    except shutil.Error:
                        pass
                    os.makedirs(saved, exist_ok=True)
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
    for name in sorted(by_family):
        print("  %-22s %5d mutants, %d failures%s" % (
            name, by_family[name]["mutants"], by_family[name]["failures"],
            ", %d refused for the other's lock" % by_family[name]["refused"]
            if "refused" in by_family[name] else ""))
    if args.summary:
        with open(args.summary, "w") as f:
            json.dump(dict(counts, seconds=round(elapsed), seed=args.seed, families=by_family), f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
