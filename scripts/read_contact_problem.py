#!/usr/bin/python3
"""Reads back a contact problem written by mbfem (Output/Write contact
problems = true; the format is in doc/contact_problems.md) and checks it
without mbfem:

  /usr/bin/python3 scripts/read_contact_problem.py RESULTS/BASE-problem-0001.json [--tolerance 1e-10]

1. u = W r + q + G alpha from the files against the u mbfem wrote, and the
   floating blocks' equilibrium G^T r + f = 0.
2. The forces again: the linear system of the states mbfem found (stick:
   u = 0; slip: u_N = 0 and r_T = -(c A + mu r_N) s, in 3D with mbfem's
   linearised direction law; open and held directions: r = 0; G^T r + f =
   0), solved here with numpy, against mbfem's r and alpha.
3. The joint law pair by pair (Table 1): a stuck pair inside its cone and
   above its tension limit, a slipping one on the cone with its shear
   against its slip, an open one with r = 0 and a gap.

Each check prints its largest relative difference; the script exits with
1 if any exceeds the tolerance (default 1e-10 for 1 and 2; 1e-8 for 3, the
state iteration's own tolerance for the cone), else 0. Needs python3-numpy.
"""
import json
import os
import sys

import numpy as np


def read_matrix_market(path):
    with open(path) as f:
        header = f.readline()
        if not header.startswith("%%MatrixMarket matrix coordinate real general"):
            sys.exit("%s: not a coordinate real general Matrix Market file" % path)
        line = f.readline()
        while line.startswith("%"):
            line = f.readline()
        m, n, nnz = (int(x) for x in line.split())
        a = np.zeros((m, n))
        for _ in range(nnz):
            i, j, v = f.readline().split()
            a[int(i) - 1, int(j) - 1] += float(v)
    return a


def load(path):
    with open(path) as f:
        p = json.load(f)
    folder = os.path.dirname(path)
    p["Wm"] = read_matrix_market(os.path.join(folder, p["W"]))
    p["Gm"] = read_matrix_market(os.path.join(folder, p["G"]))
    for key in ("q", "f", "r", "alpha", "u", "mu", "cohesion", "tension",
                "direction_stiffness", "tensile_slip"):
        p[key] = np.array(p[key], dtype=float)
    p["slip_direction"] = np.array(p["slip_direction"], dtype=float)
    p["held"] = np.array(p["held"], dtype=bool)
    return p


def relative(a, b):
    scale = max(np.max(np.abs(b)) if b.size else 0.0, 1e-300)
    return float(np.max(np.abs(a - b)) / scale) if a.size else 0.0


def displacement_scale(p):
    """The size of the terms of u = W r + q + G alpha: u itself is
    round-off where every pair sticks."""
    terms = (p["Wm"] @ p["r"], p["q"], p["Gm"] @ p["alpha"])
    return max(max(np.max(np.abs(t)) if t.size else 0.0 for t in terms), 1e-300)


def solve_states(p):
    """The linear system of mbfem's states, as ContactSolver::pair_equations
    writes it; returns r and alpha."""
    dim, n = p["dimension"], p["n_pairs"]
    n_r, n_a = n * dim, p["n_alpha"]
    W, G, q = p["Wm"], p["Gm"], p["q"]
    A = np.zeros((n_r + n_a, n_r + n_a))
    b = np.zeros(n_r + n_a)
    # u = W r + G alpha + q: the row of u_i in the unknowns, and its constant.
    u_row = np.hstack([W, G])
    for k in range(n):
        state = p["state"][k]
        s = p["slip_direction"][k]
        beta = p["direction_stiffness"][k]
        for d in range(dim):
            row = k * dim + d
            if p["held"][k][d] or state == "open":
                A[row, row] = 1.0
            elif d == 0 or state == "stick":
                A[row] = u_row[row]
                b[row] = -q[row]
            else:
                # a tensile slip (r_N < 0) has no friction
                mu = 0.0 if p["tensile_slip"][k] else p["mu"][k]
                A[row, row] += 1.0
                A[row, k * dim] += mu * s[d]
                b[row] = -p["cohesion"][k] * s[d]
                for e in range(1, dim if beta > 0 else 1):
                    m = (1.0 if d == e else 0.0) - s[d] * s[e]
                    A[row] += beta * m * u_row[k * dim + e]
                    b[row] -= beta * m * q[k * dim + e]
    for a in range(n_a):
        A[n_r + a, :n_r] = G[:, a]
        b[n_r + a] = -p["f"][a]
    # Equilibrate rows and columns first: force rows and displacement rows
    # differ by the flexibility's scale, and a 3D wedge's system reached a
    # condition number of 1e22 unscaled.
    rows = 1.0 / np.maximum(np.max(np.abs(A), axis=1), 1e-300)
    A = A * rows[:, None]
    b = b * rows
    cols = 1.0 / np.maximum(np.max(np.abs(A), axis=0), 1e-300)
    x = np.linalg.solve(A * cols[None, :], b) * cols
    return x[:n_r], x[n_r:]


def joint_law(p, tolerance):
    """Largest violation of each state's conditions, relative to the
    largest force or displacement."""
    dim, n = p["dimension"], p["n_pairs"]
    r = p["r"].reshape(n, dim)
    u = p["u"].reshape(n, dim)
    force = max(np.max(np.abs(r)), 1e-300)
    disp = displacement_scale(p)
    worst = {"stick": 0.0, "slip": 0.0, "open": 0.0}
    for k in range(n):
        state = p["state"][k]
        rn, rt = r[k, 0], r[k, 1:]
        mu = 0.0 if p["tensile_slip"][k] else p["mu"][k]
        limit = p["cohesion"][k] + mu * max(rn, 0.0)
        if p["tied"][k]:
            continue
        if state == "stick":
            v = max(np.linalg.norm(rt) - limit, -rn - p["tension"][k], 0.0) / force
            v = max(v, np.max(np.abs(u[k])) / disp)
        elif state == "slip":
            v = abs(np.linalg.norm(rt) - limit) / force
            v = max(v, abs(u[k, 0]) / disp)
            # the shear against the slip (up to the iteration's tolerance)
            if np.linalg.norm(u[k, 1:]) > 1e-6 * disp:
                v = max(v, max(0.0, float(rt @ u[k, 1:])) / (force * disp))
        else:
            v = max(np.max(np.abs(r[k])) / force, max(-u[k, 0], 0.0) / disp)
        worst[state] = max(worst[state], v)
    return worst


def main():
    args = sys.argv[1:]
    if not args:
        sys.exit(__doc__)
    tolerance = 1e-10
    if "--tolerance" in args:
        i = args.index("--tolerance")
        tolerance = float(args[i + 1])
        del args[i:i + 2]
    p = load(args[0])
    if not p["solved"]:
        print("%s: a failed increment (no solution to check); %d pairs, "
              "%d floating modes" % (args[0], p["n_pairs"], p["n_alpha"]))
        return 0
    counts = {s: p["state"].count(s) for s in ("stick", "slip", "open")}
    print("%s: %dD, %d pairs (stick/slip/open %d/%d/%d), %d floating modes, "
          "W with %d entries" % (os.path.basename(args[0]), p["dimension"],
                                 p["n_pairs"], counts["stick"], counts["slip"],
                                 counts["open"], p["n_alpha"],
                                 int(np.count_nonzero(p["Wm"]))))
    u = p["Wm"] @ p["r"] + p["q"] + p["Gm"] @ p["alpha"]
    checks = [("u = W r + q + G alpha",
               float(np.max(np.abs(u - p["u"]))) / displacement_scale(p),
               tolerance)]
    if p["n_alpha"]:
        eq = p["Gm"].T @ p["r"] + p["f"]
        # relative to the forces that balance, not to f (0 without loads)
        scale = max(np.max(np.abs(p["f"])),
                    np.max(np.abs(p["Gm"].T)) * np.max(np.abs(p["r"])), 1e-300)
        checks.append(("G^T r + f = 0", float(np.max(np.abs(eq))) / scale,
                       tolerance))
    r, alpha = solve_states(p)
    checks.append(("r solved here against mbfem's", relative(r, p["r"]), tolerance))
    if p["n_alpha"]:
        checks.append(("alpha solved here against mbfem's",
                       relative(alpha, p["alpha"]), tolerance))
    for state, v in joint_law(p, tolerance).items():
        if counts[state]:
            checks.append(("joint law, %s pairs" % state, v, 1e-8))
    failed = 0
    for name, value, limit in checks:
        ok = value <= limit
        failed += not ok
        print("  %-36s %.3e  (at most %.0e) %s" % (name, value, limit,
                                                  "yes" if ok else "NO"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
