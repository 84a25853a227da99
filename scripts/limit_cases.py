#!/usr/bin/env python3
"""Runs the limit cases of issue 20 at multiples of their known limits.

Each model of parameters/ (incline blocks, gravity dam, toppling pair, 3D
wedge) has a limit in closed form (see each .prm). This script writes, for
each multiple lambda of that limit, a parameter file that includes the
model and sets the friction (and cohesion) for the factor F = lambda *
F_limit (mu = tan(phi) / F, c / F), runs mbfem on it and prints a line per
run: the exit code and what it means,

  converged        exit 0: every increment found equilibrium
  certified-none   exit 2: no statically admissible contact forces exist
  not-converged    exit 3: the iteration failed although admissible forces
                   exist, also along the mechanism of the LP's limit
  none-along-mechanism
                   exit 4: admissible forces exist, but none with the
                   shear against the slip of that mechanism (limit
                   equilibrium along it fails)
  error            exit 1: anything else (also an undecided certificate)

the state iterations summed over the increments, how many increments the
load path, the semismooth Newton method and the load continuation
concluded (P/N/C; the fast iteration alone did not), how many step
halvings were tried, the wall time and the first line of the message.
Below the limit (lambda < 1) 'converged' is expected; above it
'certified-none', except where a model's statics (LP) limit lies above its
closed form (the 3D wedge: 1.3737 against Hoek and Bray's 1.3249). Between
the two, the wedge must end with 'none-along-mechanism' (Hoek and Bray's
limit is the limit equilibrium of the LP's mechanism, the slide along the
line of intersection); for the others any verdict but 'converged' above
the closed form is accepted, and the line says so.

The matrices of issue 20 (--matrix, default all):

  incline     the two incline blocks at 0.95, 0.999, 1.001 (and 1.05)
  dam         the dam, c = 0, phi = 45, at 0.99 and 1.01 x 1.920, p = 1
              and 2, joint elements of 1, 0.5, 0.25 m, 5 and 20 water
              increments
  dam-c       the dam, c = 200 kPa, phi = 35, at 0.5, 0.9, 0.99, 1.01,
              1.05 x 2.4111, p = 1 and 2, 1 m, 5 increments
  toppling    the toppling pair, gravity ramped over 1, 2 and 10
              increments, at 0.99, 0.999, 1.001, 1.01 x 1.32377
  column      Goodman and Bray's column of eight blocks on a stepped base
              (issue 13), the weight in 1 increment (gravity/1) and
              ramped over 5 (gravity/5), at 0.9 ... 1.01 x 2.039446
              (scripts/goodman_bray.py; LP limit 2.3011)
  wedge       the 3D wedge, p = 1 and 2, F = 0.3 ... 0.99 x 1.3249 (ten
              values) and 1.01, 1.03, 1.1, 1.5 x 1.3249

  python3 scripts/limit_cases.py [--mbfem build/mbfem] [--matrix dam]
                                 [--only 'p=1'] [--quick] [--markdown]
  python3 scripts/limit_cases.py --matrix wedge --bisect 0.005

With --bisect W, instead of the table: for each case, bisection on lambda
from [0.9, 1.1] (converged at 0.9, not at 1.1) to a bracket of width W,
printing the limit mbfem finds (the bracket, times the closed form) and
the larger distance of its ends from the closed form, in per cent.

The dam meshes with 0.5 and 0.25 m joint elements are generated with
gmsh from meshes/gravity_dam.geo (-setnumber h) into the work folder
(gmsh 4.8.4 regenerates the committed 1 m mesh byte for byte).
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTCOME = {0: "converged", 2: "certified-none", 3: "not-converged",
           4: "none-along-mechanism"}
MATRICES = ["incline", "dam", "dam-c", "toppling", "column", "wedge"]


class Case:
    """One model at several multiples of its limit."""

    def __init__(self, matrix, name, base, f_limit, tan_phi, cohesion,
                 lambdas, extra="", lp_limit=None, names=(),
                 kinematic=False):
        self.matrix, self.name, self.base = matrix, name, base
        self.f_limit, self.tan_phi, self.cohesion = f_limit, tan_phi, cohesion
        self.lambdas, self.extra = lambdas, extra
        # The statics (LP) limit where it differs from the closed form:
        # between the two, either verdict is right.
        self.lp_limit = lp_limit or f_limit
        # Blocks the certificate's mechanism must name beyond the limit.
        self.names = names
        # The closed form is the limit equilibrium of the mechanism of the
        # LP's limit (the wedge: Hoek and Bray along the line of
        # intersection), so between the two limits the run must end with
        # exit code 4 (or 2), not 3.
        self.kinematic = kinematic

    def expected(self, lam):
        factor = lam * self.f_limit
        if factor < self.f_limit:
            return ("converged",)
        if factor <= self.lp_limit and self.kinematic:
            return ("none-along-mechanism", "certified-none")
        if factor <= self.lp_limit:
            return ("converged", "certified-none", "none-along-mechanism",
                    "not-converged")
        return ("certified-none",)


def dam_mesh(work, h):
    """The dam mesh with joint elements of h m (committed for h = 1,
    generated with gmsh into the work folder otherwise)."""
    committed = os.path.join(SOURCE, "meshes", "gravity_dam_h%g.msh" % h)
    if os.path.exists(committed):
        return committed
    path = os.path.join(work, "gravity_dam_h%g.msh" % h)
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-2", "-format", "msh22", "-setnumber", "h",
                        str(h), os.path.join(SOURCE, "meshes",
                                             "gravity_dam.geo"), "-o", path],
                       check=True, stdout=subprocess.DEVNULL)
    return path


def section(name, **entries):
    """A parameter-file subsection setting the given entries."""
    body = "".join("  set %s = %s\n" % (k.replace("_", " "), v)
                   for k, v in entries.items())
    return "subsection %s\n%send\n" % (name, body)


def dam_extra(work, p, h, n):
    return (section("Finite element", Polynomial_degree=p)
            + section("Mesh", Mesh_file=dam_mesh(work, h))
            + section("Load history", Number_of_increments=n))


def incline_cases(quick):
    t24 = math.tan(math.radians(24.2))
    t6 = math.tan(math.radians(6.57))
    near = [0.95, 0.999, 1.001, 1.05] if not quick else [0.95, 1.05]
    return [Case("incline", "incline 24.2 deg p=1", "incline_24deg.prm",
                 1.0, t24, 0., near),
            Case("incline", "incline 6.57 deg p=2", "incline_6deg.prm",
                 1.0, t6, 0., near)]


def dam_cases(work, quick):
    out = []
    for p in ([1, 2] if not quick else [2]):
        for h in ([1, 0.5, 0.25] if not quick else [1]):
            for n in ([5, 20] if not quick else [5]):
                out.append(Case("dam", "dam p=%d h=%g n=%d" % (p, h, n),
                                "gravity_dam.prm", 1.92, 1.0, 0.,
                                [0.99, 1.01], dam_extra(work, p, h, n)))
    return out


def dam_cohesion_cases(work, quick):
    t35 = math.tan(math.radians(35.))
    lambdas = [0.5, 0.9, 0.99, 1.01, 1.05] if not quick else [0.99, 1.01]
    return [Case("dam-c", "dam c=200k p=%d h=1 n=5" % p, "gravity_dam.prm",
                 2.4111, t35, 200e3, lambdas, dam_extra(work, p, 1, 5))
            for p in ([1, 2] if not quick else [2])]


def toppling_cases(quick):
    out = []
    for n in ([1, 2, 10] if not quick else [1, 10]):
        extra = (section("Boundary conditions", Gravity_ramp_time=1)
                 + section("Load history", Number_of_increments=n))
        out.append(Case("toppling", "toppling gravity/%d" % n,
                        "toppling_pair.prm", 1.32377, 1.0, 0.,
                        [0.99, 0.999, 1.001, 1.01] if not quick else
                        [0.99, 1.01], extra,
                        names=("block 2", "block 3")))
    return out


def column_cases(quick):
    """Goodman and Bray's column (parameters/toppling_column.prm): F =
    1/tan(phi) at the limit from scripts/goodman_bray.py."""
    out = []
    for n in ([1, 5] if not quick else [1]):
        extra = (section("Boundary conditions", Gravity_ramp_time=1)
                 + section("Load history", Number_of_increments=n))
        # The certificate's rigid-block limit is 2.3011 (contact forces
        # anywhere on the faces, not at the corners as Goodman and Bray).
        out.append(Case("column", "column gravity/%d" % n,
                        "toppling_column.prm", 2.039446, 1.0, 0.,
                        [0.9, 0.95, 0.98, 0.99, 1.0, 1.003, 1.01]
                        if not quick else [0.99, 1.01], extra,
                        lp_limit=2.3011))
    return out


def wedge_cases(quick):
    t35 = math.tan(math.radians(35.))
    limit = 1.3249
    if quick:
        lambdas = [0.3 / limit, 0.99, 1.01, 1.1]
    else:
        # Ten values of F from 0.3 to 0.99 x 1.3249, then beyond.
        lambdas = [(0.3 + (0.99 * limit - 0.3) * i / 9) / limit
                   for i in range(10)] + [1.01, 1.03, 1.1, 1.5]
    p2 = (section("Finite element", Polynomial_degree=2)
          + section("Mesh", Mesh_file=os.path.join(SOURCE, "meshes",
                                                   "wedge_3d_4.msh")))
    return [Case("wedge", "wedge 3D p=1", "wedge_3d.prm", limit, t35, 0.,
                 lambdas, "", lp_limit=1.3737, kinematic=True),
            Case("wedge", "wedge 3D p=2", "wedge_3d.prm", limit, t35, 0.,
                 lambdas, p2, lp_limit=1.3737, kinematic=True)]


def cases(work, quick, matrices):
    out = []
    if "incline" in matrices:
        out += incline_cases(quick)
    if "dam" in matrices:
        out += dam_cases(work, quick)
    if "dam-c" in matrices:
        out += dam_cohesion_cases(work, quick)
    if "toppling" in matrices:
        out += toppling_cases(quick)
    if "column" in matrices:
        out += column_cases(quick)
    if "wedge" in matrices:
        out += wedge_cases(quick)
    return out


def write_case(work, case, lam):
    """The parameter file of case at lam x its limit; returns its path."""
    factor = lam * case.f_limit
    folder = os.path.join(work, "%s-%.6g" % (re.sub(r"[ /]", "_", case.name),
                                             lam))
    os.makedirs(folder, exist_ok=True)
    base_path = os.path.join(SOURCE, "parameters", case.base)
    # The mesh path of the base file is relative to parameters/: give it
    # absolute (a later 'set' in 'extra' overrides it).
    mesh = None
    for line in open(base_path):
        if line.strip().startswith("set Mesh file"):
            mesh = os.path.join(SOURCE, "parameters",
                                line.split("=", 1)[1].strip())
    prm = os.path.join(folder, "case.prm")
    with open(prm, "w") as f:
        f.write("include %s\n" % base_path)
        f.write(section("Mesh", Mesh_file=mesh))
        f.write(section("Contact",
                        Friction_coefficient="%.9g" % (case.tan_phi / factor),
                        Cohesion="%.9g" % (case.cohesion / factor)))
        f.write(section("Output", Write_VTU="false"))
        f.write(case.extra)
    return prm


def summarise(stdout, stderr):
    """(iterations summed, increments concluded by the load path, the
    semismooth Newton method and the load continuation as 'P/N/C',
    halvings, the certificate's strength factor or None, first message
    line, every message line)."""
    iterations = halvings = 0
    concluded = {"load path": 0, "semismooth Newton": 0,
                 "load continuation": 0}
    for line in stdout.splitlines():
        m = re.match(r"\s*increment \d+/\d+, t = [^:]*: (\d+) iteration"
                     r"\(s\)( \(fast \d+, (load path|semismooth Newton|"
                     r"load continuation) "
                     r"\d+\))?", line)
        if m:
            iterations += int(m.group(1))
            if m.group(3):
                concluded[m.group(3)] += 1
        halvings += "failed (" in line and "halving" in line
    m = re.search(r"strength factor ([0-9.]+)|divided by up to ([0-9.]+)",
                  stderr)
    strength = float(m.group(1) or m.group(2)) if m else None
    message = ""
    for line in stderr.splitlines():
        if "Load increment" in line or "Statics certificate" in line:
            message = line.strip()
            break
    path = "%d/%d/%d" % (concluded["load path"],
                         concluded["semismooth Newton"],
                         concluded["load continuation"])
    return iterations, path, halvings, strength, message, stderr


def mechanism_factor(stderr):
    """The certificate's mechanism factor (limit equilibrium along the
    mechanism of the LP's limit), or None."""
    m = re.search(r"divided by up to ([0-9.]+) \(mechanism factor", stderr)
    return float(m.group(1)) if m else None


def run(mbfem, work, case, lam):
    prm = write_case(work, case, lam)
    start = time.time()
    result = subprocess.run([mbfem, prm], cwd=os.path.dirname(prm),
                            capture_output=True, text=True)
    seconds = time.time() - start
    return (result.returncode, seconds) + summarise(result.stdout,
                                                    result.stderr)


def verdict(case, lam, code, stderr):
    """'' if the run is what the limit says, else why not."""
    outcome = OUTCOME.get(code, "error")
    expected = case.expected(lam)
    if outcome not in expected:
        return "[expected %s]" % " or ".join(expected)
    if outcome in ("certified-none", "none-along-mechanism"):
        missing = [n for n in case.names
                   if not re.search(n + r": translation along", stderr)]
        if missing:
            return "[mechanism does not name %s]" % ", ".join(missing)
    return ""


def bisect(mbfem, work, case, width):
    """The bracket [lo, hi] of lambda (x the closed-form limit) between the
    last multiple that converged and the first that did not, narrowed by
    bisection from [0.9, 1.1] to width; the runs it took."""
    lo, hi, runs = 0.9, 1.1, []
    for lam in (lo, hi):
        runs.append((lam, run(mbfem, work, case, lam)[0]))
    if runs[0][1] != 0 or runs[1][1] == 0:
        return None, None, runs
    while hi - lo > width:
        mid = 0.5 * (lo + hi)
        code = run(mbfem, work, case, mid)[0]
        runs.append((mid, code))
        if code == 0:
            lo = mid
        else:
            hi = mid
    return lo, hi, runs


def bisect_all(args, work, matrices):
    """Prints, per case, the limit mbfem finds against the closed form."""
    print("%-24s %9s %9s %9s %8s %5s  %s" % (
        "case", "closed", "mbfem lo", "mbfem hi", "error %", "runs",
        "exit codes above"))
    wrong = 0
    start = time.time()
    for case in cases(work, False, matrices):
        if args.only not in case.name:
            continue
        lo, hi, runs = bisect(args.mbfem, work, case, args.bisect)
        if lo is None:
            wrong += 1
            print("%-24s %9.5f  no bracket in [0.9, 1.1]: %s" % (
                case.name, case.f_limit, runs), flush=True)
            continue
        # The error bound: the farther end of the bracket from 1.
        error = 100. * max(abs(lo - 1.), abs(hi - 1.))
        above = sorted({c for lam, c in runs if c != 0})
        print("%-24s %9.5f %9.5f %9.5f %8.3f %5d  %s" % (
            case.name, case.f_limit, lo * case.f_limit, hi * case.f_limit,
            error, len(runs), above), flush=True)
    print("%d case(s) without a bracket; %.0f s in all; work folder %s" % (
        wrong, time.time() - start, work))
    return 1 if wrong else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--matrix", default="all",
                        help="one of %s, or all" % ", ".join(MATRICES))
    parser.add_argument("--only", default="", help="run the cases whose "
                        "name contains this")
    parser.add_argument("--quick", action="store_true",
                        help="fewer multiples and variants")
    parser.add_argument("--markdown", action="store_true",
                        help="print the table as Markdown")
    parser.add_argument("--work", default="")
    parser.add_argument("--bisect", type=float, default=0.,
                        help="instead of the table: bisect on lambda in "
                        "[0.9, 1.1] to this width, converged below, not "
                        "above (issue 13's limits within 1 %%)")
    args = parser.parse_args()
    matrices = MATRICES if args.matrix == "all" else [args.matrix]
    if any(m not in MATRICES for m in matrices):
        sys.exit("--matrix: '%s' is none of %s, all" % (args.matrix,
                                                        ", ".join(MATRICES)))
    work = args.work or tempfile.mkdtemp(prefix="mbfem-limits-")
    os.makedirs(work, exist_ok=True)
    if args.bisect > 0.:
        return bisect_all(args, work, matrices)
    if args.markdown:
        print("| case | lambda | F | exit | result | iterations | "
              "increments by load path/Newton/continuation | halvings | "
              "LP limit | mechanism limit | s | message |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    else:
        print("%-24s %7s %8s %4s %-20s %5s %4s %4s %8s %8s %7s  %s" % (
            "case", "lambda", "F", "exit", "result", "iter", "P/N/C", "halv",
            "LP", "mech", "seconds", "first message"))
    wrong = 0
    start = time.time()
    for case in cases(work, args.quick, matrices):
        if args.only not in case.name:
            continue
        for lam in case.lambdas:
            code, seconds, iterations, path, halvings, strength, message, \
                stderr = run(args.mbfem, work, case, lam)
            note = verdict(case, lam, code, stderr)
            wrong += note != ""
            factor = lam * case.f_limit
            # The certificate's LP limit, F x its strength factor (at the
            # loads of the failing step).
            lp = "%.5f" % (factor * strength) if strength else "-"
            # The mechanism's limit equilibrium, F x its factor.
            kinematic = mechanism_factor(stderr)
            mech = "%.5f" % (factor * kinematic) if kinematic else "-"
            row = (case.name, lam, factor, code, OUTCOME.get(code, "error"),
                   iterations, path, halvings, lp, mech, seconds,
                   (note + " " if note else "") + message[:100])
            if args.markdown:
                print("| %s | %.4f | %.5f | %d | %s | %d | %s | %d | %s | "
                      "%s | %.1f | %s |" % row, flush=True)
            else:
                print("%-24s %7.4f %8.5f %4d %-20s %5d %5s %4d %8s %8s %7.1f"
                      "  %s" % row, flush=True)
    print("%d run(s) differ from the limit's verdict; %.0f s in all; work "
          "folder %s" % (wrong, time.time() - start, work))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
