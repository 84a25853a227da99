#!/usr/bin/python3
"""Pictures of a strength-reduction run (Mode = strength reduction):

  /usr/bin/python3 scripts/plot_strength_reduction.py RESULTS/BASE INCREMENT OUT_PREFIX [TITLE] [INTERFACE]

e.g. results/gravity_dam_safety 5 doc/figures/gravity_dam_safety. Reads
RESULTS/BASE-strength-reduction.csv (a line per trial: F, result, largest
displacement, largest slip) and RESULTS/BASE-pairs-IIII.csv (the joint at
the factor of safety, written by the final run), and writes

  OUT_PREFIX_trials.png  the largest displacement against F, converged
                         trials as dots, failed ones as crosses at the top
  OUT_PREFIX_joint.png   along the joint (x): the water pressure p_w, the
                         effective normal traction r_N / A and the shear
                         |r_T| / A, with the pairs' states (stick, slip,
                         open) as the colour of the shear points; only the
                         pairs of interface INTERFACE (1, 2, ...) if given.

Needs python3-matplotlib.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_table(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    return list(csv.DictReader(lines))


def plot_trials(rows, out, title):
    fig, ax = plt.subplots(figsize=(6, 4))
    conv = [r for r in rows if r["result"] == "converged"]
    fail = [r for r in rows if r["result"] != "converged"]
    top = max([float(r["largest_displacement"]) for r in conv] + [1e-300])
    ax.plot([float(r["F"]) for r in conv],
            [float(r["largest_displacement"]) for r in conv], "o",
            label="converged")
    ax.plot([float(r["F"]) for r in fail], [1.1 * top] * len(fail), "x",
            color="C3", label="failed (no equilibrium or not converged)")
    ax.set_xlabel("strength reduction factor F")
    ax.set_ylabel("largest displacement component (m)")
    ax.set_title(title)
    ax.legend()
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def plot_joint(rows, out, title):
    x = [float(r["x"]) for r in rows]
    order = sorted(range(len(x)), key=lambda i: x[i])
    x = [x[i] for i in order]
    rows = [rows[i] for i in order]
    kpa = 1e-3
    fig, ax = plt.subplots(figsize=(7, 4))
    if "water_pressure" in rows[0]:
        ax.plot(x, [kpa * float(r["water_pressure"]) for r in rows], "-",
                color="C0", label="water pressure p_w")
    ax.plot(x, [kpa * float(r["normal_traction"]) for r in rows], "-",
            color="C1", label="effective normal traction r_N / A")
    colours = {"stick": "C2", "slip": "C3", "open": "0.6"}
    for state, colour in colours.items():
        pts = [(xi, kpa * abs(float(r["tangential_traction_1"])))
               for xi, r in zip(x, rows) if r["state"] == state]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o",
                    color=colour, markersize=4, label="|shear|, " + state)
    ax.set_xlabel("x along the joint (m)")
    ax.set_ylabel("kPa")
    ax.set_title(title)
    ax.legend(fontsize=8)
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    base, increment, prefix = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    title = sys.argv[4] if len(sys.argv) > 4 else base
    pairs = read_table("%s-pairs-%04d.csv" % (base, increment))
    joint = "the joint"
    if len(sys.argv) > 5:
        pairs = [r for r in pairs if r["interface"] == sys.argv[5]]
        joint = "interface " + sys.argv[5]
    plot_trials(read_table(base + "-strength-reduction.csv"),
                prefix + "_trials.png", title + ": trials")
    plot_joint(pairs, prefix + "_joint.png", title + ": " + joint + " at F")


if __name__ == "__main__":
    main()
