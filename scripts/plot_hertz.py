#!/usr/bin/python3
"""Plots the contact tractions of mbfem's Hertz/Mindlin runs against the
closed forms (Hertz p(x), Cattaneo-Mindlin q(x), design.md example 1).

  /usr/bin/python3 scripts/plot_hertz.py OUT.png "title" A.csv:label B.csv:label ...

Each CSV is a pair table written by mbfem (results/BASE-pairs-NNNN.csv);
the tractions are force / tributary area of each pair, on the upper disk.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

A, P0, C, MU = 0.69099, 9.2132, 0.50400, 0.2


def hertz(x):
    return P0 * math.sqrt(1 - (x / A) ** 2) if abs(x) < A else 0.0


def mindlin(x):
    q = MU * hertz(x)
    if abs(x) < C:
        q -= MU * P0 * C / A * math.sqrt(1 - (x / C) ** 2)
    return q


def read(path):
    rows = [r for r in csv.DictReader(l for l in open(path) if not l.startswith("#"))]
    rows.sort(key=lambda r: float(r["x"]))
    x = [float(r["x"]) for r in rows]
    return (x, [float(r["normal_traction"]) for r in rows],
            [float(r["tangential_traction_1"]) for r in rows],
            [r["state"] for r in rows])


def main(image, title, *runs):
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    xs = [-1.0 + 2.0 * i / 800 for i in range(801)]
    top.plot(xs, [hertz(x) for x in xs], "k-", linewidth=1.2, label="Hertz")
    bottom.plot(xs, [mindlin(x) for x in xs], "k-", linewidth=1.2,
                label="Cattaneo-Mindlin")
    markers = "os^vD<>"
    for i, run in enumerate(runs):
        path, label = run.split(":", 1)
        x, p, q, state = read(path)
        top.plot(x, p, markers[i % 7] + "-", markersize=3.5, linewidth=0.6,
                 label=label)
        bottom.plot(x, q, markers[i % 7] + "-", markersize=3.5, linewidth=0.6,
                    label=label)
    top.set_ylabel("normal traction p (N/mm^2)")
    bottom.set_ylabel("tangential traction q (N/mm^2)")
    bottom.set_xlabel("x (mm)")
    top.set_title(title)
    for ax in (top, bottom):
        ax.axvline(-A, color="0.7", linewidth=0.5)
        ax.axvline(A, color="0.7", linewidth=0.5)
        ax.grid(True, linewidth=0.3)
        ax.legend(fontsize=8)
    bottom.axvline(-C, color="0.85", linestyle="--", linewidth=0.5)
    bottom.axvline(C, color="0.85", linestyle="--", linewidth=0.5)
    bottom.set_xlim(-1.0, 1.0)
    figure.tight_layout()
    figure.savefig(image, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:])
