#!/usr/bin/python3
"""The paper's Fig. 7 from mbfem's runs of the stacked cantilevers: the
normal gap of the contact pairs along the beams, condensed against the
monolithic Lagrange-multiplier reference, with the pairs' states.

  /usr/bin/python3 scripts/plot_stacked_gap.py OUT.png A.csv:label[:style] ...

Each CSV is a pair table written by mbfem (BASE-pairs-NNNN.csv). The gap
is plotted in mm on the pairs of the centre line y = 1 (the gap varies
across the width by less than the line width); slipping and stuck pairs
are marked. style: 'line' (default) or 'marker'.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    centre = [r for r in rows if abs(float(r["y"]) - 1.0) < 1e-9]
    centre.sort(key=lambda r: float(r["x"]))
    x = [float(r["x"]) for r in centre]
    g = [1e3 * float(r["gap"]) for r in centre]
    s = [r["state"] for r in centre]
    largest = max(1e3 * float(r["gap"]) for r in rows)
    counts = {k: sum(1 for r in rows if r["state"] == k) for k in ("stick", "slip", "open")}
    return x, g, s, largest, counts, len(rows)


def main():
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(7.5, 5.4))
    for spec in sys.argv[2:]:
        parts = spec.split(":")
        path, label = parts[0], parts[1]
        style = parts[2] if len(parts) > 2 else "line"
        x, g, s, largest, counts, n = read(path)
        text = "%s: %d pairs, %d/%d/%d stick/slip/open, max gap %.3g mm" % (
            label, n, counts["stick"], counts["slip"], counts["open"], largest)
        if style == "marker":
            ax.plot(x, g, "o", mfc="none", ms=7, label=text)
        else:
            line, = ax.plot(x, g, "-", label=text)
            for state, marker in (("slip", "^"), ("stick", "s")):
                xs = [xi for xi, si in zip(x, s) if si == state]
                gs = [gi for gi, si in zip(g, s) if si == state]
                if xs:
                    ax.plot(xs, gs, marker, color=line.get_color(), ms=5)
    ax.axhline(5.36e-3, color="grey", ls=":", lw=1)
    ax.text(0.1, 5.4e-3, "paper's largest gap 5.36e-3 mm", va="bottom", fontsize=8, color="grey")
    ax.set_xlabel("x along the beams (m); clamp at x = 0, load at x = 10")
    ax.set_ylabel("normal gap (mm), pairs at y = 1")
    ax.set_title("Stacked cantilevers (paper's Fig. 7): normal gap of the pairs\n"
                 "squares: stuck, triangles: slipping, the rest open", fontsize=10)
    ax.set_ylim(bottom=-2e-4, top=6e-3)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.16))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=130)


if __name__ == "__main__":
    main()
