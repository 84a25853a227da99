#!/usr/bin/python3
"""Plots the tables of mbfem's element-order studies (CSV written by
`mbfem parameters/order_study_*.prm`) as error against cell size, one line per
degree, with reference slopes. Uses Debian's python3-matplotlib.

  /usr/bin/python3 scripts/plot_order_study.py results/order_study_lame.csv \
      doc/figures/order_study_lame.png "Lame cylinder"
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(table, image, title):
    rows = list(csv.DictReader(open(table)))
    degrees = sorted({int(r["degree"]) for r in rows})
    figure, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, column, label, shift in ((axes[0], "displacement_error", "u", 1),
                                     (axes[1], "stress_error", "sigma", 0)):
        for p in degrees:
            mine = [r for r in rows if int(r["degree"]) == p]
            h = [2.0 ** -int(r["refinement"]) for r in mine]
            e = [float(r[column]) for r in mine]
            line, = ax.loglog(h, e, "o-", label="p = %d" % p)
            # reference slope h^(p + shift) through the coarsest point
            rate = p + shift
            ax.loglog(h, [e[0] * (x / h[0]) ** rate for x in h], ":",
                      color=line.get_color(), linewidth=0.8)
        ax.set_xlabel("relative cell size h / h_0")
        ax.set_ylabel("relative L2 error of %s" % label)
        ax.set_title("%s: %s (dotted: h^(p+%d))" % (title, label, shift)
                     if shift else "%s: %s (dotted: h^p)" % (title, label))
        ax.grid(True, which="major", linewidth=0.3)
        ax.legend()
    figure.tight_layout()
    figure.savefig(image, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:4])
