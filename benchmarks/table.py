#!/usr/bin/env python3
"""Reads the logs of benchmarks/run.sh and prints doc/benchmarks.md."""
import math
import os
import platform
import re
import subprocess
import sys

work = sys.argv[1]
args = sys.argv[2:]
command = args[args.index("--command") + 1] if "--command" in args else ""
names = [a for a in args[: args.index("--command")]] if "--command" in args else args

PHASES = [("factorisation", "factorisation"), ("flexibility", "flexibility"),
          ("load response", "load response"),
          ("contact iterations", "state iterations"),
          ("field recovery", "recovery"), ("output", "output")]


def parse(path):
    if not os.path.exists(path):
        return None
    text = open(path, errors="replace").read()
    r = {"dofs": sum(int(x) for x in re.findall(r"degrees of freedom: (\d+)", text)),
         "pairs": sum(int(x) for x in re.findall(r"\)[:,] (\d+) pairs", text)),
         "phases": {}}
    m = re.search(r"mbfem: (\d+) blocks", text)
    r["blocks"] = int(m.group(1)) if m else 1
    m = re.search(r"increment (\d+)/(\d+)", text)
    r["increments"] = int(m.group(2)) if m else 1
    for name, _ in PHASES + [("assembly", ""), ("monolithic reference", ""),
                             ("monolithic assembly", "")]:
        m = re.search(r"\| " + re.escape(name) + r" +\| +\d+ \| +([\d.e+-]+)s", text)
        r["phases"][name] = float(m.group(1)) if m else 0.
    m = re.search(r"Total wallclock time elapsed since start +\| +([\d.e+-]+)s", text)
    r["total"] = float(m.group(1)) if m else float("nan")
    m = re.search(r"condensed ([\d.e+-]+) \(", text)
    r["condensed"] = float(m.group(1)) if m else float("nan")
    m = re.search(r"monolithic ([\d.e+-]+) \(", text)
    r["monolithic"] = float(m.group(1)) if m else float("nan")
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
    r["memory"] = int(m.group(1)) / 1024 ** 2 if m else float("nan")
    r["failed"] = "Total wallclock" not in text
    return r


def fmt(x, digits=3):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return f"{x:.{digits}g}"


def fit(points):
    """Exponent b of y = a x^b by least squares in log-log."""
    points = [(math.log(x), math.log(y)) for x, y in points if x > 0 and y > 0]
    if len(points) < 2:
        return float("nan")
    n = len(points)
    mx = sum(p[0] for p in points) / n
    my = sum(p[1] for p in points) / n
    sxx = sum((p[0] - mx) ** 2 for p in points)
    if sxx == 0.:
        return float("nan")
    return sum((p[0] - mx) * (p[1] - my) for p in points) / sxx


rows, fits = [], []
for name in names:
    r = parse(os.path.join(work, name + ".log"))
    if r is None:
        continue
    e = parse(os.path.join(work, name + "-elastic.log"))
    if e is None and name.endswith("_100"):
        e = parse(os.path.join(work, name[:-4] + "-elastic.log"))
    elastic = (sum(e["phases"][p] for p in ("assembly", "factorisation", "load response"))
               if e and not e["failed"] else float("nan"))
    rows.append((name, r, elastic))
    if re.fullmatch(r"stacked_\d+", name) and not r["failed"]:
        fits.append((r["pairs"], r["condensed"], r["memory"]))

try:
    threads = os.environ.get("OPENBLAS_NUM_THREADS", str(os.cpu_count()))
    blas = os.path.realpath("/etc/alternatives/libblas.so.3-x86_64-linux-gnu")
except OSError:
    blas = "unknown"

out = []
out.append("# Benchmarks: the multi-body method against the monolithic solve\n")
out.append("Made by `" + command.strip() + "` (benchmarks/run.sh; "
           "benchmarks/table.py writes this page). Machine: "
           f"{os.cpu_count()} cores, {platform.machine()}, shared with other "
           "users and noisy: ratios are from one run, where the condensed and "
           "the monolithic formulation ran side by side (`Contact/Formulation "
           "= both`), absolute times move by a factor of 2 or more from run to "
           "run. BLAS/LAPACK: " + blas + f" (OpenBLAS pthread, {threads} "
           + ("thread" if threads == "1" else "threads") + "). Block solves and the monolithic system: Trilinos Amesos, "
           "MUMPS for the 3D stacked models, KLU for the others "
           "(`Linear solver/Direct solver`); flexibilities: MUMPS 5.5.1 (PORD "
           "ordering), selected entries of K^-1 (ICNTL(30)), for blocks with "
           "at least 500 contact DoFs, unit-load solves below; state system "
           "(`Contact/State system = auto`): dense LU for the stacked and "
           "Hertz models, sparse LU (UMFPACK) for the walls and the cube; the "
           "monolithic reference factorises the whole Lagrange-multiplier "
           "system once per state trial.\n")
out.append("Times in seconds (wall). Phases are those of the condensed "
           "formulation (the timer table each run prints); *condensed* and "
           "*monolithic* are the program's own 'time of the contact "
           "formulation(s) alone'; *whole / elastic* is the whole run divided "
           "by one linear elastic solve (assembly, factorisation, solve) of "
           "the same mesh as one bonded block. Peak memory: maximum resident "
           "set size from /usr/bin/time -v, of the whole run (both "
           "formulations where both ran).\n")
head = ["model", "DoFs", "pairs", "blocks", "incr."] + [p[1] for p in PHASES] + \
       ["condensed", "monolithic", "mono / cond", "whole run", "peak GiB", "whole / elastic"]
out.append("| " + " | ".join(head) + " |")
out.append("|" + "---|" * len(head))
for name, r, elastic in rows:
    cells = [name, str(r["dofs"]), str(r["pairs"]), str(r["blocks"]), str(r["increments"])]
    cells += [fmt(r["phases"][p[0]]) for p in PHASES]
    ratio = r["monolithic"] / r["condensed"] if r["condensed"] > 0 else float("nan")
    cells += [fmt(r["condensed"]), fmt(r["monolithic"]), fmt(ratio, 2),
              fmt(r["total"]), fmt(r["memory"], 2),
              fmt(r["total"] / elastic if elastic > 0 else float("nan"), 2)]
    if r["failed"]:
        cells[0] += " (failed)"
    out.append("| " + " | ".join(cells) + " |")
out.append("")
if len({f[0] for f in fits}) >= 2:
    out.append("Fitted exponents over the stacked models with 10 increments "
               f"({', '.join(str(f[0]) for f in fits)} pairs): condensed time "
               f"~ pairs^{fit([(f[0], f[1]) for f in fits]):.2f}, peak memory "
               f"~ pairs^{fit([(f[0], f[2]) for f in fits]):.2f}.\n")
notes = os.path.join(os.path.dirname(os.path.abspath(__file__)), "notes.md")
if os.path.exists(notes):
    out.append(open(notes).read())
print("\n".join(out))
