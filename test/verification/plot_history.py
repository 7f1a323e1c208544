#!/usr/bin/python3
"""Plots energies from an impm history CSV (kinetic, strain, their sum, the external work).

usage: plot_history.py HISTORY.csv OUTPUT.png "title"
Uses Debian's python3 with python3-matplotlib.
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

history, png, title = sys.argv[1], sys.argv[2], sys.argv[3]
rows = list(csv.DictReader(open(history)))
t = [float(r["time"]) for r in rows]
fig, ax = plt.subplots(figsize=(7, 4))
for column, label in (("kinetic_energy", "kinetic"), ("strain_energy", "strain"),
                      ("total_energy", "total")):
    ax.plot(t, [float(r[column]) for r in rows], label=label)
if any(float(r["external_work"]) != 0 for r in rows):
    ax.plot(t, [float(r["external_work"]) for r in rows], "--", label="external work")
ax.set_xlabel("time")
ax.set_ylabel("energy")
ax.set_title(title)
ax.legend()
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(png, dpi=120)
