#!/usr/bin/env python3
"""Seeded random single blocks on inclines against their rigid-block limit.

Issue 20's must-show: at least 100 blocks (random size, slope 0-30 deg,
friction, cohesion, a lateral pressure on the up-slope face, p = 1 or 2,
1 to 20 increments, gravity ramped or not) run at 0.97 and 1.03 of their
rigid-block limit; none may fail at 0.97, none converge at 1.03.

The limit is the strength factor of the rigid-block linear program (the
statics certificate's), which for one block on one plane is in closed
form: the pairs' friction capacity is mu N whatever the distribution of
the normal forces, their cohesion c times the area of the pairs that keep
it, and the moments balance as long as the normal resultant lies within
the base, so

  F = (c A_c + W cos(theta) tan(phi)) / (W sin(theta) + P),

W the weight, A_c the area of the unbroken pairs (the base length L before
any breaks), P = p_lat H the lateral thrust down-dip. Blocks are drawn so
that the normal resultant lies in the middle 70 % of the base (the block
slides before it topples), and so that 0.2 < F < 5 (mu = tan(phi) / F
neither tiny nor huge).

Cohesion is drawn for one block in three. A pair that opens breaks and
loses its cohesion for good (doc/state_iteration.md), which lowers the
limit to the LP without cohesion at the broken pairs. The run at 0.97 of
F(L) reads the pairs it broke from its last pair file; if it broke any,
the block's limit is F(A_c) with those pairs' area removed, and both runs
are repeated at 0.97 and 1.03 of it (up to six rounds, until the run at
0.97 breaks no further pairs). The line of such a block names the rounds.

  python3 scripts/random_inclines.py [--count 100] [--seed 20] [--mbfem ...]
                                     [--test] [--dimension 3]

--dimension 3 (issue 27's 3D campaign): the block is L x Bw x H on a
plane dipping at theta, meshed with hexahedra (meshes/incline_block.geo
with dim3), and pushed, in one block of two, by a body force in the slope
plane at an angle psi from the dip (0 to 90 deg), of up to half its unit
weight, ramped with t (a body force acts at the centroid, so that the
push turns the block about no axis: tests/state_incline_45_3d*). With
T the tangential resultant (W sin(theta) + B cos(psi), B sin(psi)) and
N = W cos(theta),

  F = (c A_c + N tan(phi)) / |T|,

the normal resultant lying at (H / 2) T / N from the base's centre, which
is drawn within the middle 70 % of the base in both directions. Each
block runs at 0.95, 0.99 and 1.01 of its limit (the rounds as above, at
0.95); the target is the issue's: no exit code 3 at 0.95 and 0.99, none
converged at 1.01.

Writes the parameter file and the mesh of every block into the work
folder, runs mbfem, and prints one line per block and a summary with the
counts per outcome (exit code: 0 converged, 2 certified no equilibrium, 3
not converged although admissible, 1 other). --test leaves out the times
and the work folder, for a stored output (tests/campaigns/).
"""

import argparse
import glob
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTCOME = {0: "converged", 2: "certified-none", 3: "not-converged"}
UNIT_WEIGHT = 25e3
BELOW, BEYOND = 0.97, 1.03
# The multiples of the limit each block runs at, per dimension: the first
# decides the rounds, the last is beyond the limit.
LAMBDAS = {2: (BELOW, BEYOND), 3: (0.95, 0.99, 1.01)}
MAX_ROUNDS = 6


def forces(b, t=1.):
    """(W, N, T) at pseudo-time t: the weight, its normal component, the
    driving force (the weight ramped with t if b["ramp"], the lateral
    pressure or the push always); in 3D T is the size of the tangential
    resultant."""
    th = math.radians(b["theta"])
    volume = b["L"] * b["H"] * b.get("Bw", 1.)
    W = UNIT_WEIGHT * volume * (min(t, 1.) if b["ramp"] else 1.)
    if b.get("dim", 2) == 2:
        return (W, W * math.cos(th),
                W * math.sin(th) + t * b["p_lat"] * b["H"])
    push = t * b["push"] * UNIT_WEIGHT * volume
    psi = math.radians(b["psi"])
    return (W, W * math.cos(th),
            math.hypot(W * math.sin(th) + push * math.cos(psi),
                       push * math.sin(psi)))


def base_area(b):
    return b["L"] * b.get("Bw", 1.)


def limit(b, area):
    """The rigid-block strength factor with cohesion on 'area' of base."""
    _, N, T = forces(b)
    return (b["c"] * area + N * math.tan(math.radians(b["phi"]))) / T


def cohesive_area(b, factor, t):
    """The area with cohesion for which 'factor' is the limit at time t."""
    _, N, T = forces(b, t)
    return (factor * T - N * math.tan(math.radians(b["phi"]))) / b["c"]


def draw(rng):
    """One block; resampled until it slides before it topples."""
    while True:
        b = dict(L=rng.uniform(0.5, 4.), H=rng.uniform(0.3, 3.),
                 theta=rng.uniform(0., 30.), phi=rng.uniform(10., 45.),
                 c=(rng.uniform(0., 20e3) if rng.random() < 1. / 3 else 0.),
                 p_lat=(rng.uniform(0., 10e3) if rng.random() < 0.5 else 0.),
                 p=rng.choice([1, 2]), n_inc=rng.randint(1, 20),
                 ramp=rng.random() < 0.5)
        th = math.radians(b["theta"])
        W, N, T = forces(b)
        if T <= 0.:
            continue
        # Position of the normal resultant from the down-dip corner.
        x_n = (W * (b["L"] * math.cos(th) - b["H"] * math.sin(th)) / 2
               - b["p_lat"] * b["H"] * b["H"] / 2) / N
        if not 0.15 * b["L"] < x_n < 0.85 * b["L"]:
            continue
        b["limit"] = limit(b, b["L"])
        if not 0.2 < b["limit"] < 5.:
            continue
        b["n"] = max(2, min(12, int(round(4 * b["L"] / b["p"]))))
        return b


def draw_3d(rng):
    """One 3D block; resampled until it slides before it topples."""
    while True:
        b = dict(dim=3, L=rng.uniform(0.5, 3.), Bw=rng.uniform(0.5, 3.),
                 H=rng.uniform(0.3, 2.), theta=rng.uniform(0., 30.),
                 phi=rng.uniform(10., 45.),
                 c=(rng.uniform(0., 20e3) if rng.random() < 1. / 3 else 0.),
                 push=(rng.uniform(0., 0.5) if rng.random() < 0.5 else 0.),
                 psi=rng.uniform(0., 90.), p=rng.choice([1, 2]),
                 n_inc=rng.randint(1, 10), ramp=rng.random() < 0.5)
        th, psi = math.radians(b["theta"]), math.radians(b["psi"])
        W, N, T = forces(b)
        if T <= 0.:
            continue
        # The normal resultant's offset from the base's centre, (H / 2) T / N
        # along the dip and across it.
        push = b["push"] * W
        along = b["H"] / 2 * (W * math.sin(th) + push * math.cos(psi)) / N
        across = b["H"] / 2 * push * math.sin(psi) / N
        if abs(along) > 0.35 * b["L"] or abs(across) > 0.35 * b["Bw"]:
            continue
        b["limit"] = limit(b, base_area(b))
        if not 0.2 < b["limit"] < 5.:
            continue
        b["n"] = max(2, min(6, int(round(2 * b["L"] / b["p"]))))
        b["nb"] = max(2, min(6, int(round(2 * b["Bw"] / b["p"]))))
        return b


def write_mesh(folder, i, b):
    mesh = os.path.join(folder, "block%03d.msh" % i)
    extra = []
    if b.get("dim", 2) == 3:
        extra = ["-setnumber", "dim3", "1", "-setnumber", "Bw",
                 repr(b["Bw"]), "-setnumber", "nb", str(b["nb"])]
    if not os.path.exists(mesh):
        subprocess.run(["gmsh", "-%d" % b.get("dim", 2), "-format", "msh22",
                        "-setnumber", "L", repr(b["L"]),
                        "-setnumber", "H", repr(b["H"]),
                        "-setnumber", "theta", repr(b["theta"]),
                        "-setnumber", "n", str(b["n"])] + extra +
                       [os.path.join(SOURCE, "meshes", "incline_block.geo"),
                        "-o", mesh], check=True, stdout=subprocess.DEVNULL)
    return mesh


def loads_3d(b):
    """The 3D case's boundary conditions: the base's bottom held, and the
    push as a body force in the block only (above the slope plane
    -x sin(theta) + z cos(theta) = 0), down the dip (-cos, 0, -sin) and
    along y, ramped with t."""
    th, psi = math.radians(b["theta"]), math.radians(b["psi"])
    g = b["push"] * UNIT_WEIGHT
    inside = "-x*%.12g + z*%.12g > 0" % (math.sin(th), math.cos(th))
    components = [-g * math.cos(psi) * math.cos(th), g * math.sin(psi),
                  -g * math.cos(psi) * math.sin(th)]
    expression = "; ".join("if(%s, %.12g*t, 0)" % (inside, v)
                           for v in components)
    return """  set Prescribed displacement boundary ids = 1: xyz
  set Gravity ramp time = %s
  subsection Body force
    set Variable names      = x,y,z,t
    set Function expression = %s
  end
""" % ("1" if b["ramp"] else "0", expression)


def loads_2d(b):
    """The 2D case's boundary conditions: the base's bottom held, and the
    lateral pressure on the up-slope face (boundary 2), pushing down-dip,
    ramped with the load history."""
    th = math.radians(b["theta"])
    traction = "%.9g*t; %.9g*t" % (-b["p_lat"] * math.cos(th),
                                   -b["p_lat"] * math.sin(th))
    return """  set Prescribed displacement boundary ids = 1: xy
  set Traction boundary ids = 2
  set Gravity ramp time = %s
  subsection Traction
    set Function expression = %s
  end
""" % ("1" if b["ramp"] else "0", traction)


def write_case(folder, name, mesh, b, factor):
    dim = b.get("dim", 2)
    prm = os.path.join(folder, name + ".prm")
    with open(prm, "w") as f:
        f.write("""# Random %sincline block (scripts/random_inclines.py): %s
# Run at the strength factor F = %.9g.
set Dimension = %d
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
%send
subsection Load history
  set Number of increments = %d
end
subsection Contact
  set Interfaces           = blocks 1:2
  set Friction coefficient = %.9g
  set Cohesion             = %.9g
end
subsection Output
  set Base name = block
  set Directory = %s
  set Write VTU = false
end
""" % ("" if dim == 2 else "3D ",
            {k: (round(v, 4) if isinstance(v, float) else v)
             for k, v in b.items()}, factor, dim, mesh, b["p"], UNIT_WEIGHT,
            loads_2d(b) if dim == 2 else loads_3d(b), b["n_inc"],
            math.tan(math.radians(b["phi"])) / factor, b["c"] / factor,
            name))
    return prm


def broken_area(results):
    """Area of the broken pairs in the last pair file in 'results'."""
    files = sorted(glob.glob(os.path.join(results, "block-pairs-*.csv")))
    if not files:
        return 0.
    area = 0.
    header = None
    for line in open(files[-1]):
        if line.startswith("#"):
            continue
        fields = line.strip().split(",")
        if header is None:
            header = fields
            continue
        row = dict(zip(header, fields))
        if row["broken"] == "1":
            area += float(row["area"])
    return area


def run(mbfem, folder, name, mesh, b, factor):
    """(outcome, seconds, broken area at the end, (the certificate's LP
    limit, its time t) or None, load-path increments)."""
    prm = write_case(folder, name, mesh, b, factor)
    results = os.path.join(folder, name)
    shutil.rmtree(results, ignore_errors=True)
    start = time.time()
    r = subprocess.run([mbfem, prm], cwd=folder, capture_output=True,
                       text=True)
    seconds = time.time() - start
    m = re.search(r"Statics certificate at t = ([0-9.e+-]+): no statically "
                  r"admissible contact forces exist.*?strength factor "
                  r"([0-9.]+)", r.stderr, re.S)
    lp = (factor * float(m.group(2)), float(m.group(1))) if m else None
    path = len(re.findall(r"load path \d+\)", r.stdout))
    if r.returncode not in (0, 2):
        sys.stderr.write("%s exited with %d:\n%s\n" % (prm, r.returncode,
                                                       r.stderr))
    return (OUTCOME.get(r.returncode, "error"), seconds, broken_area(results),
            lp, path)


def campaign_block(mbfem, work, i, b):
    """Runs block i at the multiples of its limit of its dimension
    (LAMBDAS), rounds as described above at the first; returns (reference
    limit, rounds, the results in that order)."""
    mesh = write_mesh(work, i, b)
    lambdas = LAMBDAS[b.get("dim", 2)]

    def name(lam):
        if b.get("dim", 2) == 2:
            return "block%03d-%s" % (i, "below" if lam < 1. else "beyond")
        return "block%03d-%.2f" % (i, lam)

    area = base_area(b)
    for rounds in range(1, MAX_ROUNDS + 1):
        reference = limit(b, area)
        first = run(mbfem, work, name(lambdas[0]), mesh, b,
                    lambdas[0] * reference)
        if b["c"] == 0. or rounds == MAX_ROUNDS:
            break
        # The area the run kept cohesive: from its last pair file if it
        # converged, from the certificate's limit if it failed.
        if first[0] == "converged":
            kept = base_area(b) - first[2]
        elif first[3] is not None:
            kept = cohesive_area(b, *first[3])
        else:
            break
        if kept >= area - 1e-6 * b["L"]:
            break
        area = max(kept, 0.)
    results = [first]
    for lam in lambdas[1:]:
        results.append(run(mbfem, work, name(lam), mesh, b, lam * reference))
    return reference, rounds, results


def describe(result, test, unit="m"):
    """The outcome; out of test mode also the broken area, the
    certificate's LP limit, the increments the load path concluded and the
    time, which round-off may move (a pair breaking or not)."""
    outcome, seconds, broken, lp, path = result
    text = "%-14s" % outcome
    if test:
        return text.strip()
    if broken > 0.:
        text += " broken %.3f %s" % (broken, unit)
    if lp is not None:
        text += " LP %.4f at t = %.4g" % lp
    if path:
        text += " path %d" % path
    return text + " %.1f s" % seconds


def block_line(i, b, reference, rounds, results, test):
    if b.get("dim", 2) == 2:
        head = ("block %3d L=%.2f H=%.2f theta=%5.2f phi=%4.1f c=%5.0f "
                "p_lat=%5.0f p=%d inc=%2d ramp=%d" % (
                    i, b["L"], b["H"], b["theta"], b["phi"], b["c"],
                    b["p_lat"], b["p"], b["n_inc"], b["ramp"]))
    else:
        head = ("block %3d L=%.2f Bw=%.2f H=%.2f theta=%5.2f phi=%4.1f "
                "c=%5.0f push=%.2f psi=%4.1f p=%d inc=%2d ramp=%d" % (
                    i, b["L"], b["Bw"], b["H"], b["theta"], b["phi"],
                    b["c"], b["push"], b["psi"], b["p"], b["n_inc"],
                    b["ramp"]))
    text = head + " F=%.4f%s" % (
        b["limit"] if test else reference,
        " (round %d, closed form %.4f)" % (rounds, b["limit"])
        if rounds > 1 and not test else "")
    for lam, result in zip(LAMBDAS[b.get("dim", 2)], results):
        text += " | %.2f: %s" % (
            lam, describe(result, test, "m" if b.get("dim", 2) == 2 else "m2"))
    return text


def summary(counts, lambdas, seed, count, seconds):
    """The summary lines, and whether the target is met (every run below
    the limit converged, every one beyond it certified); 'seconds' None in
    test mode."""
    lines = ["", "summary (seed %d, %d blocks%s):" % (
        seed, count, "" if seconds is None else ", %.0f s" % seconds)]
    for key in sorted(counts):
        lines.append("  at %.2f of the limit, %s: %-15s %d"
                     % (key + (counts[key],)))
    passed = True
    for lam in lambdas:
        wanted = "converged" if lam < 1. else "certified-none"
        n = sum(v for k, v in counts.items()
                if k[0] == lam and k[2] == wanted)
        lines.append(("converged at %.2f of the limit: %d of %d" if lam < 1.
                      else "certified no equilibrium (exit 2) at %.2f of the "
                      "limit: %d of %d") % (lam, n, count))
        passed = passed and n == count
    return lines, passed


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=100)
    parser.add_argument("--seed", type=int, default=20)
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--work", default="")
    parser.add_argument("--blocks", default="",
                        help="run only these blocks (comma-separated "
                        "indices; the others are drawn, not run)")
    parser.add_argument("--test", action="store_true",
                        help="no times, no work folder (stored output)")
    parser.add_argument("--test-output", default="",
                        help="also write the test-mode output to this file")
    parser.add_argument("--dimension", type=int, default=2, choices=(2, 3),
                        help="3: blocks in 3D, at 0.95, 0.99 and 1.01 of "
                        "their limit")
    args = parser.parse_args()
    if not os.access(args.mbfem, os.X_OK):
        sys.exit("--mbfem: %s is not an executable" % args.mbfem)
    work = args.work or tempfile.mkdtemp(prefix="mbfem-random-inclines-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    counts = {}
    test_lines = []
    start = time.time()
    lambdas = LAMBDAS[args.dimension]
    for i in range(args.count):
        b = draw(rng) if args.dimension == 2 else draw_3d(rng)
        if args.blocks and str(i) not in args.blocks.split(","):
            continue
        result = campaign_block(args.mbfem, work, i, b)
        cohesive = "c>0" if b["c"] > 0 else "c=0"
        for lam, run_result in zip(lambdas, result[2]):
            key = (lam, cohesive, run_result[0])
            counts[key] = counts.get(key, 0) + 1
        print(block_line(i, b, *result, args.test), flush=True)
        test_lines.append(block_line(i, b, *result, True))
    n_run = sum(counts.values()) // len(lambdas)
    lines, passed = summary(counts, lambdas, args.seed, n_run,
                            None if args.test else time.time() - start)
    print("\n".join(lines))
    if args.test_output:
        with open(args.test_output, "w") as f:
            f.write("\n".join(test_lines + summary(counts, lambdas, args.seed,
                                                   n_run, None)[0])
                    + "\n")
    if not args.test:
        print("work folder:", work)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
