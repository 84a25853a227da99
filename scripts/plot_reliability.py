#!/usr/bin/python3
"""Pictures of a reliability run (Mode = reliability):

  /usr/bin/python3 scripts/plot_reliability.py RESULTS/BASE-reliability.csv OUT_PREFIX [TITLE [EXACT]]

Reads the CSV mbfem writes (a line per sample: the values drawn, F, the
verdict at F = 1, the trials) and writes

  OUT_PREFIX_distribution.png  the histogram of F and its empirical CDF,
                               the line F = 1 marked (samples without a
                               factor are left out, their count in the
                               title)
  OUT_PREFIX_convergence.png   P(F < 1) against the number of samples
                               taken so far, with Clopper and Pearson's 95 %
                               interval (scipy's beta quantiles), the
                               failures counted by the verdict at F = 1,
                               and EXACT (a closed form's P(F < 1), if given)
                               as a dashed line

Needs python3-matplotlib and python3-scipy.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from scipy.stats import beta


def interval(failures, n):
    lower = 0.0 if failures == 0 else beta.ppf(0.025, failures, n - failures + 1)
    upper = 1.0 if failures == n else beta.ppf(0.975, failures + 1, n - failures)
    return lower, upper


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    rows = list(csv.DictReader(open(sys.argv[1])))
    out, title = sys.argv[2], (sys.argv[3] if len(sys.argv) > 3 else "")
    factors = sorted(float(r["F"]) for r in rows if r["F"] not in ("nan", ""))

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.hist(factors, bins=max(10, int(math.sqrt(len(factors)))), density=True,
            color="0.75", label="histogram")
    ax2 = ax.twinx()
    ax2.step(factors, [(i + 1) / len(factors) for i in range(len(factors))],
             where="post", color="C0", label="empirical CDF")
    ax2.set_ylim(0, 1)
    ax.axvline(1.0, color="C3", linestyle="--", label="F = 1")
    ax.set_xlabel("factor of safety F")
    ax.set_ylabel("density")
    ax2.set_ylabel("P(F <= x)")
    left = len(rows) - len(factors)
    ax.set_title(title + (f" ({left} samples without F)" if left else ""))
    fig.legend(loc="upper left", bbox_to_anchor=(0.12, 0.88))
    fig.tight_layout()
    fig.savefig(out + "_distribution.png", dpi=120)

    failures, n_axis, estimate, lows, highs = 0, [], [], [], []
    for n, r in enumerate(rows, start=1):
        failures += r["verdict"] == "fails"
        lo, hi = interval(failures, n)
        n_axis.append(n)
        estimate.append(failures / n)
        lows.append(lo)
        highs.append(hi)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.fill_between(n_axis, lows, highs, color="C0", alpha=0.25,
                    label="95 % interval (Clopper-Pearson)")
    ax.plot(n_axis, estimate, color="C0", label="P(F < 1)")
    if len(sys.argv) > 4:
        ax.axhline(float(sys.argv[4]), color="C3", linestyle="--",
                   label=f"closed form {float(sys.argv[4]):.4f}")
    ax.set_xlabel("samples")
    ax.set_ylabel("probability of failure")
    ax.set_title(title)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out + "_convergence.png", dpi=120)


if __name__ == "__main__":
    main()
