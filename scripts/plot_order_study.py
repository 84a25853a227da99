#!/usr/bin/python3
"""Plots the tables of mbfem's element-order studies (CSV written by
`mbfem parameters/order_study_*.prm`) as error against cell size, one line per
degree, with reference slopes. Uses Debian's python3-matplotlib.

A model of several blocks (a 'degrees' column such as "1/3" and columns per
block id) gets one line per combination of block degrees: the model's
displacement error, then the stress error of each block, its reference slope
that of the block's own degree.

  /usr/bin/python3 scripts/plot_order_study.py results/order_study_lame.csv \
      doc/figures/order_study_lame.png "Lame cylinder"
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

# Errors below this are round-off (the studies' 'Round-off floor'): no
# reference slope is drawn through them.
ROUND_OFF = 1e-9


def panel(ax, rows, key, cases, column, rate_of, label, title):
    for case in cases:
        mine = [r for r in rows if r[key] == case]
        h = [2.0 ** -int(r["refinement"]) for r in mine]
        e = [float(r[column]) for r in mine]
        line, = ax.loglog(h, e, "o-", label="p = %s" % case)
        if e[0] > ROUND_OFF:
            # reference slope through the coarsest point
            rate = rate_of(case)
            ax.loglog(h, [e[0] * (x / h[0]) ** rate for x in h], ":",
                      color=line.get_color(), linewidth=0.8)
    ax.set_xlabel("relative cell size h / h_0")
    ax.set_ylabel("relative L2 error of %s" % label)
    ax.set_title(title)
    ax.grid(True, which="major", linewidth=0.3)
    ax.legend(fontsize="small")


def main(table, image, title):
    rows = list(csv.DictReader(open(table)))
    key = "degrees" if "degrees" in rows[0] else "degree"
    cases = []
    for r in rows:
        if r[key] not in cases:
            cases.append(r[key])
    lowest = lambda case: min(int(p) for p in case.split("/"))
    if key == "degree":
        figure, axes = plt.subplots(1, 2, figsize=(10, 4.2))
        panel(axes[0], rows, key, cases, "displacement_error",
              lambda c: lowest(c) + 1, "u",
              "%s: u (dotted: h^(p+1))" % title)
        panel(axes[1], rows, key, cases, "stress_error", lowest, "sigma",
              "%s: sigma (dotted: h^p)" % title)
    else:
        blocks = [c[len("degree_"):] for c in rows[0] if
                  c.startswith("degree_")]
        figure, axes = plt.subplots(1, 1 + len(blocks),
                                    figsize=(5 * (1 + len(blocks)), 4.6))
        panel(axes[0], rows, key, cases, "displacement_error",
              lambda c: lowest(c) + 1, "u",
              "%s: u of the model\n(dotted: h^(lowest p + 1))" % title)
        for i, b in enumerate(blocks):
            # "2": 'Block degrees = same', the one degree of every block
            own = lambda c, i=i: int(c.split("/")[i] if "/" in c else c)
            panel(axes[1 + i], rows, key, cases, "stress_error_" + b, own,
                  "sigma", "%s: sigma in block %s\n(dotted: h^p of block %s)"
                  % (title, b, b))
    figure.tight_layout()
    figure.savefig(image, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:4])
