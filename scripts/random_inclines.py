#!/usr/bin/env python3
"""Seeded random single blocks on inclines against their rigid-block limit.

Issue 20's must-show: at least 100 blocks (random size, slope 0-30 deg,
friction, cohesion, a lateral pressure on the up-slope face, p = 1 or 2,
1 to 20 increments, gravity ramped or not) run at 0.97 and 1.03 of their
rigid-block limit; none may fail at 0.97, none converge at 1.03.

The limit is the strength factor of a rigid block sliding on its base:

  F = (c L + W cos(theta) tan(phi)) / (W sin(theta) + P),

W the weight, L the base length, P = p_lat H the lateral thrust down-dip.
Blocks are drawn so that the base's normal resultant lies in the middle
70 % of the base, so that the block slides before it topples and no pair
needs tension: the rigid-block LP of the certificate then has exactly this
limit (for a block whose pairs all stay closed; a pair that opens loses its
cohesion, which the closed form does not know, so cohesion is drawn for
one block in three only and reported apart).

  python3 scripts/random_inclines.py [--count 100] [--seed 20] [--mbfem ...]

Writes NAME.prm and the mesh of every block into the work folder, runs
mbfem at both factors, and prints one line per block and a summary with
counts per outcome (exit code: 0 converged, 2 certified no equilibrium,
3 not converged although admissible, 1 other) and the time.
"""

import argparse
import math
import os
import random
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTCOME = {0: "converged", 2: "certified-none", 3: "not-converged"}
UNIT_WEIGHT = 25e3


def draw(rng):
    """One block; resampled until it slides before it topples."""
    while True:
        b = dict(L=rng.uniform(0.5, 4.), H=rng.uniform(0.3, 3.),
                 theta=rng.uniform(0.5, 30.), phi=rng.uniform(10., 45.),
                 c=(rng.uniform(0., 20e3) if rng.random() < 1. / 3 else 0.),
                 p_lat=(rng.uniform(0., 10e3) if rng.random() < 0.5 else 0.),
                 p=rng.choice([1, 2]), n_inc=rng.randint(1, 20),
                 ramp=rng.random() < 0.5)
        th = math.radians(b["theta"])
        W = UNIT_WEIGHT * b["L"] * b["H"]
        N = W * math.cos(th)
        T = W * math.sin(th) + b["p_lat"] * b["H"]
        # Position of the normal resultant from the down-dip corner.
        x_n = (W * (b["L"] * math.cos(th) - b["H"] * math.sin(th)) / 2
               - b["p_lat"] * b["H"] * b["H"] / 2) / N
        if not 0.15 * b["L"] < x_n < 0.85 * b["L"]:
            continue
        b["limit"] = (b["c"] * b["L"] + N * math.tan(math.radians(b["phi"]))) / T
        # Strength factors far from 1 make tiny or huge mu: keep 0.2..5.
        if not 0.2 < b["limit"] < 5.:
            continue
        b["n"] = max(2, min(12, int(round(4 * b["L"] / b["p"]))))
        return b


def write_case(folder, i, b, lam):
    mesh = os.path.join(folder, "block%03d.msh" % i)
    if not os.path.exists(mesh):
        subprocess.run(["gmsh", "-2", "-format", "msh22",
                        "-setnumber", "L", str(b["L"]),
                        "-setnumber", "H", str(b["H"]),
                        "-setnumber", "theta", str(b["theta"]),
                        "-setnumber", "n", str(b["n"]),
                        os.path.join(SOURCE, "meshes", "incline_block.geo"),
                        "-o", mesh], check=True, stdout=subprocess.DEVNULL)
    factor = lam * b["limit"]
    th = math.radians(b["theta"])
    # Lateral pressure on the up-slope face (boundary 2), pushing down-dip,
    # ramped with the load history.
    traction = "%.9g*t; %.9g*t" % (-b["p_lat"] * math.cos(th),
                                   -b["p_lat"] * math.sin(th))
    prm = os.path.join(folder, "block%03d-%g.prm" % (i, lam))
    with open(prm, "w") as f:
        f.write("""# Random incline block %d (seed in the summary): %s
# Rigid-block limit F = %.6f; run at %.2f of it.
set Dimension = 2
subsection Mesh
  set Source    = gmsh
  set Mesh file = %s
end
subsection Finite element
  set Polynomial degree = %d
end
subsection Material
  set Young's modulus = 2e7
  set Poisson's ratio = 0.2
  set Unit weight     = %g
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 1: xy
  set Traction boundary ids = 2
  set Gravity ramp time = %s
  subsection Traction
    set Function expression = %s
  end
end
subsection Load history
  set Number of increments = %d
end
subsection Contact
  set Interfaces           = blocks 1:2
  set Friction coefficient = %.9g
  set Cohesion             = %.9g
end
subsection Output
  set Write VTU = false
end
""" % (i, {k: (round(v, 4) if isinstance(v, float) else v)
           for k, v in b.items()}, b["limit"], lam, mesh, b["p"],
            UNIT_WEIGHT, "1" if b["ramp"] else "0", traction, b["n_inc"],
            math.tan(math.radians(b["phi"])) / factor, b["c"] / factor))
    return prm


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=100)
    parser.add_argument("--seed", type=int, default=20)
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--work", default="")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="mbfem-random-inclines-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    counts = {}
    start = time.time()
    for i in range(args.count):
        b = draw(rng)
        line = []
        for lam in (0.97, 1.03):
            prm = write_case(work, i, b, lam)
            r = subprocess.run([args.mbfem, prm], cwd=work,
                               capture_output=True, text=True)
            outcome = OUTCOME.get(r.returncode, "error")
            cohesive = "c>0" if b["c"] > 0 else "c=0"
            key = (lam, cohesive, outcome)
            counts[key] = counts.get(key, 0) + 1
            first = ""
            if r.returncode != 0:
                for l in r.stderr.splitlines():
                    if "Load increment" in l:
                        first = l.strip()[:70]
                        break
            line.append("%.2f: %-14s %s" % (lam, outcome, first))
        print("block %3d L=%.2f H=%.2f theta=%5.2f phi=%4.1f c=%7.0f "
              "p_lat=%6.0f p=%d inc=%2d ramp=%d F=%.4f | %s" % (
                  i, b["L"], b["H"], b["theta"], b["phi"], b["c"],
                  b["p_lat"], b["p"], b["n_inc"], b["ramp"], b["limit"],
                  " | ".join(line)), flush=True)
    print("\nsummary (seed %d, %d blocks, %.0f s):" % (
        args.seed, args.count, time.time() - start))
    for key in sorted(counts):
        print("  at %.2f of the limit, %s: %-15s %d" % (key + (counts[key],)))
    print("work folder:", work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
