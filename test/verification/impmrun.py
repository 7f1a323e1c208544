"""The verification scripts' shared runner: impm on a deck in a fresh directory, and what
it wrote.  Standard library only."""

import csv
import os
import shutil
import subprocess
import sys
import tempfile


class Outputs:
    """The files of one run: <directory>/<deck stem><suffix>."""

    def __init__(self, directory, stem):
        self.directory, self.stem = directory, stem

    def path(self, suffix):
        return os.path.join(self.directory, self.stem + suffix)

    def table(self, suffix):
        with open(self.path(suffix), newline="") as f:
            return list(csv.DictReader(f))

    def remove(self):
        shutil.rmtree(self.directory)


def run_deck(impm, deck, sets, prefix="impm-run-"):
    """Runs impm on deck with the --set overrides in a new directory under the current one;
    exits with impm's output when the run fails."""
    out = tempfile.mkdtemp(prefix=prefix, dir=".")
    cmd = [impm, "--output-dir", out]
    for s in sets:
        cmd += ["--set", s]
    cmd.append(deck)
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        shutil.rmtree(out, ignore_errors=True)
        sys.exit("impm failed: %s\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    return Outputs(out, os.path.splitext(os.path.basename(deck))[0])
