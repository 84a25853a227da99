#!/usr/bin/python3
"""Plots the contact tractions of mbfem's Hertz/Mindlin runs against the
closed forms (Hertz p(x), Cattaneo-Mindlin q(x), design.md example 1).

  /usr/bin/python3 scripts/plot_hertz.py OUT.png "title" A.csv:label B.csv:label ...

It also prints, for each run, the contact half-width a, the stick
half-width c, p_max and q_max against Hertz and Mindlin. Each CSV is a pair table written by mbfem (results/BASE-pairs-NNNN.csv);
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


def half_width(x, selected):
    """Half of the extent of the selected pairs (the true edge lies between
    the outermost selected pair and the next one)."""
    xs = [xi for xi, s in zip(x, selected) if s]
    return 0.5 * (max(xs) - min(xs)) if xs else 0.0


def compare(label, x, p, q, state):
    """A table of the run against the closed forms."""
    q_max_exact = MU * P0 * math.sqrt(1 - (C / A) ** 2)
    rows = [("closed pairs, half-width (mm)", A,
             half_width(x, [s != "open" for s in state])),
            ("stuck pairs, half-width (mm)", C,
             half_width(x, [s == "stick" for s in state])),
            ("p_max (N/mm^2)", P0, max(p)),
            ("q_max (N/mm^2)", q_max_exact, max(abs(v) for v in q))]
    print(f"{label}: against the closed forms (Hertz, Cattaneo-Mindlin)")
    print(f"  {'quantity':28s} {'closed form':>12s} {'mbfem':>12s} {'error':>9s}")
    for name, exact, value in rows:
        print(f"  {name:28s} {exact:12.5f} {value:12.5f} "
              f"{100 * (value - exact) / exact:+8.2f}%")
    print("  (q peaks in a cusp at x = c, which pairs spaced "
          f"{min(b - a for a, b in zip(x, x[1:]) if b > a):.3f} mm apart "
          "sample only near it)")


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
        compare(label, x, p, q, state)
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
    print(f"p(x), q(x) against Hertz and Mindlin in {image}")


if __name__ == "__main__":
    main(*sys.argv[1:])
