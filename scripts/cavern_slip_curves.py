#!/usr/bin/python3
"""Slip of the cavern's left wall along the fault against the fraction of
the excavation released, for several runs of the faulted cavern (the
paper's example 3): the figure of doc/cavern_fault.md.

  /usr/bin/python3 scripts/cavern_slip_curves.py OUT.png LABEL=RESULTS/BASE ...

Each RESULTS/BASE-pairs-NNNN.csv gives t (its first line) and the slip of
the pair nearest the left wall (x < -15 m, where the fault enters the
cavern). Prints the table it draws. Needs Debian's python3-matplotlib.
"""
import csv
import glob
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def left_wall_slip(path):
    with open(path) as f:
        t = float(re.search(r"t = ([0-9.eE+-]+)", f.readline()).group(1))
        rows = list(csv.DictReader(f))
    rows = [r for r in rows if float(r["x"]) < -15]
    wall = max(rows, key=lambda r: float(r["x"]))
    return t, 1e3 * abs(float(wall["slip_1"])), float(wall["x"])


def main():
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for spec in sys.argv[2:]:
        label, base = spec.rsplit("=", 1)
        points = sorted(left_wall_slip(p) for p in glob.glob(base + "-pairs-*.csv"))
        if not points:
            sys.exit("no %s-pairs-*.csv" % base)
        t = [p[0] for p in points]
        s = [p[1] for p in points]
        print("%-28s last t = %.4f, left-wall slip %.2f mm (pair at x = %.2f m)"
              % (label, t[-1], s[-1], points[-1][2]))
        ax.plot(t, s, "-", label=label)
        ax.plot(t[-1], s[-1], "o", color=ax.lines[-1].get_color(), ms=4)
    ax.axhline(40.45, color="grey", ls=":", lw=1)
    ax.text(0.45, 41.2, "paper: 40.45 mm (full excavation)", fontsize=8, color="grey")
    ax.set_ylim(-2, 45)
    ax.set_xlabel("fraction of the excavation released, t")
    ax.set_ylabel("slip of the left wall along the fault (mm)")
    ax.set_title("Faulted cavern: left-wall slip during excavation\n"
                 "(dot: last converged increment)", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
