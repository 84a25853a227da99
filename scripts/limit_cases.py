#!/usr/bin/env python3
"""Runs the limit cases of issue 20 at multiples of their known limits.

Each model of parameters/ (incline blocks, gravity dam, toppling pair, 3D
wedge) has a limit in closed form (see each .prm). This script writes, for
each multiple lambda of that limit, a parameter file that includes the
model and sets the friction (and cohesion) for the factor F = lambda *
F_limit (mu = tan(phi) / F, c / F), runs mbfem on it and prints what
happened, from mbfem's exit code:

  converged        exit 0: every increment found equilibrium
  certified-none   exit 2: no statically admissible contact forces exist
  not-converged    exit 3: the iteration failed although admissible forces
                   exist (a failure of the iteration)
  error            exit 1: anything else (also an undecided certificate)

Below the limit (lambda < 1) 'converged' is right; above it
'certified-none'. Run from anywhere:

  python3 scripts/limit_cases.py [--mbfem build/mbfem] [--only dam] [--quick]

Meshes other than the committed ones (the dam at 0.5 and 0.25 m joint
elements) are generated with gmsh into the work folder.
"""

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTCOME = {0: "converged", 2: "certified-none", 3: "not-converged"}


def dam_mesh(work, h):
    """The dam mesh with joint elements of h m (committed for h = 1)."""
    if h == 1:
        return os.path.join(SOURCE, "meshes", "gravity_dam_h1.msh")
    path = os.path.join(work, "gravity_dam_h%g.msh" % h)
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-2", "-format", "msh22", "-setnumber", "h",
                        str(h), os.path.join(SOURCE, "meshes",
                                             "gravity_dam.geo"), "-o", path],
                       check=True, stdout=subprocess.DEVNULL)
    return path


def cases(work, quick):
    """(name, base .prm, F_limit, tan(phi), cohesion, lambdas, extra)."""
    t24 = math.tan(math.radians(24.2))
    t6 = math.tan(math.radians(6.57))
    t35 = math.tan(math.radians(35.))
    near = [0.95, 0.999, 1.001, 1.05] if not quick else [0.95, 1.05]
    out = [
        ("incline 24.2 deg p=1", "incline_24deg.prm", 1.0, t24, 0., near, ""),
        ("incline 6.57 deg p=2", "incline_6deg.prm", 1.0, t6, 0., near, ""),
    ]
    for p in ([1, 2] if not quick else [2]):
        for h in ([1, 0.5, 0.25] if not quick else [1]):
            for n in ([5, 20] if not quick else [5]):
                extra = ("subsection Finite element\n  set Polynomial degree"
                         " = %d\nend\nsubsection Mesh\n  set Mesh file = %s\n"
                         "end\nsubsection Load history\n  set Number of "
                         "increments = %d\nend\n" % (p, dam_mesh(work, h), n))
                out.append(("dam p=%d h=%g n=%d" % (p, h, n),
                            "gravity_dam.prm", 1.92, 1.0, 0.,
                            [0.99, 1.01], extra))
    for n in ([1, 2, 10] if not quick else [1, 10]):
        extra = ("subsection Boundary conditions\n  set Gravity ramp time = "
                 "1\nend\nsubsection Load history\n  set Number of increments"
                 " = %d\nend\n" % n)
        out.append(("toppling gravity/%d" % n, "toppling_pair.prm", 1.32377,
                    1.0, 0., [0.99, 1.01], extra))
    wedge = [0.3, 0.99, 1.01, 1.1] if quick else \
        [0.3, 0.5, 0.7, 0.9, 0.99, 1.01, 1.03, 1.1, 1.5]
    out.append(("wedge 3D p=1", "wedge_3d.prm", 1.3249, t35, 0., wedge, ""))
    out.append(("wedge 3D p=2", "wedge_3d.prm", 1.3249, t35, 0., wedge,
                "subsection Finite element\n  set Polynomial degree = 2\nend\n"
                "subsection Mesh\n  set Mesh file = %s\nend\n"
                % os.path.join(SOURCE, "meshes", "wedge_3d_4.msh")))
    return out


def run(mbfem, work, name, base, f_limit, tan_phi, cohesion, lam, extra):
    factor = lam * f_limit
    folder = os.path.join(work, "%s-%g" % (name.replace(" ", "_")
                                            .replace("/", "_"), lam))
    os.makedirs(folder, exist_ok=True)
    base_path = os.path.join(SOURCE, "parameters", base)
    # The mesh path of the base file is relative to parameters/: give it
    # absolute, unless 'extra' sets its own.
    mesh = None
    for line in open(base_path):
        if line.strip().startswith("set Mesh file"):
            mesh = os.path.join(SOURCE, "parameters",
                                line.split("=", 1)[1].strip())
    prm = os.path.join(folder, "case.prm")
    with open(prm, "w") as f:
        f.write("include %s\n" % base_path)
        f.write("subsection Mesh\n  set Mesh file = %s\nend\n" % mesh)
        f.write("subsection Contact\n  set Friction coefficient = %.9g\n"
                "  set Cohesion = %.9g\nend\n" % (tan_phi / factor,
                                                  cohesion / factor))
        f.write("subsection Output\n  set Write VTU = false\nend\n")
        f.write(extra)
    start = time.time()
    result = subprocess.run([mbfem, prm], cwd=folder, capture_output=True,
                            text=True)
    seconds = time.time() - start
    message = ""
    for line in result.stderr.splitlines():
        if "Load increment" in line or "Statics certificate" in line:
            message = line.strip()[:90]
            break
    return OUTCOME.get(result.returncode, "error"), seconds, message


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--only", default="", help="run the cases whose "
                        "name contains this")
    parser.add_argument("--quick", action="store_true",
                        help="fewer multiples and variants")
    parser.add_argument("--work", default="")
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="mbfem-limits-")
    os.makedirs(work, exist_ok=True)
    print("%-24s %7s %9s %-15s %7s  %s" % ("case", "lambda", "F", "result",
                                          "seconds", "first message"))
    wrong = 0
    for name, base, f_limit, tan_phi, c, lambdas, extra in cases(work,
                                                                 args.quick):
        if args.only not in name:
            continue
        for lam in lambdas:
            outcome, seconds, message = run(args.mbfem, work, name, base,
                                            f_limit, tan_phi, c, lam, extra)
            expected = "converged" if lam < 1 else "certified-none"
            wrong += outcome != expected
            print("%-24s %7.3f %9.5f %-15s %7.1f  %s%s" % (
                name, lam, lam * f_limit, outcome, seconds,
                "" if outcome == expected else "[expected %s] " % expected,
                message), flush=True)
    print("%d case(s) differ from the limit's verdict; work folder %s"
          % (wrong, work))
    return 0


if __name__ == "__main__":
    sys.exit(main())
