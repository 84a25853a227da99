#!/usr/bin/python3
"""Solves a 2D contact problem written by mbfem as a sequence of convex
quadratic programs: De Saxce's fixed point (issue 62, part 2; a prototype
of the method the state chain lacks, doc/state_iteration.md, "A method
for the first increment").

The problem (doc/contact_problems.md): u = W r + q + G alpha, G^T r + f = 0,
per pair Coulomb's law with cohesion c A, no tension. With the shift s_k of
pair k's normal gap held fixed, the problem

    min 1/2 r^T W r + (q + mu s e_N)^T r
    s.t. |r_T| <= c A + mu r_N  (every pair),  G^T r + f = 0

is a convex QP (W is symmetric and positive semidefinite: the blocks'
flexibility). Its optimality conditions say: u + mu s e_N lies in the
negative normal cone of the Mohr-Coulomb cone at r, alpha the equalities'
multipliers. Where s_k = |u_T,k| at the answer, that is Coulomb's law
exactly (De Saxce's bipotential; Acary, Cadoux, Lemarechal and Malick,
ZAMM 91 (2011) 155-175, who prove the existence of a fixed point, hence a
solution, wherever statics admits forces strictly inside the cones). The
QP is feasible exactly when rigid-block statics admits forces (mbfem's
certificate, here an LP decides it first): an infeasible QP proves that
there is no solution. The
iteration s <- (1 - omega) s + omega |u_T| is not proved to converge; it
stops after --iterations. A joint that opens with cohesion to lose breaks
(c = 0) and the fixed point runs again, as in mbfem.

Each QP is solved by CVXOPT's interior-point method (Debian's
python3-cvxopt), in MN and mm. The answer is checked against the joint law
with scripts/check_contact_problem_2d.py's check().

  /usr/bin/python3 scripts/desaxce_fixed_point_2d.py PROBLEM.json
      [--omega 0.5] [--iterations 500]

Exit code: 0 a solution found and checked (violations below 1e-7), 2 no
solution (a QP is infeasible: statics admits no forces), 1 anything else
(the fixed point did not settle, a QP failed, a model it does not handle:
3D, tension limits, tensile slip, held directions, tied pairs).
"""
import argparse
import collections
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_contact_problem_2d import Scaled, check, unsupported  # noqa: E402
from read_contact_problem import load  # noqa: E402

TOLERANCE = 1e-7     # the check's violations, relative (its scales)
QP_TOLERANCE = 1e-11  # CVXOPT's gaps, in MN and mm
SETTLED = 1e-9       # |s_new - s| / max|u|


def solve_qp(S, q_shifted, c):
    """The QP with the shifted gaps; (status, r, alpha)."""
    from cvxopt import matrix, solvers
    solvers.options["show_progress"] = False
    for key in ("abstol", "reltol", "feastol"):
        solvers.options[key] = QP_TOLERANCE
    solvers.options["maxiters"] = 200
    rows, h = cone_rows(S, c)
    W = 0.5 * (S.W + S.W.T)
    equalities = (matrix(S.G.T.copy()), matrix(-S.f)) if S.na else (None,
                                                                      None)
    answer = solvers.qp(matrix(W), matrix(q_shifted), matrix(rows),
                        matrix(h), *equalities)
    alpha = np.array(answer["y"]).ravel() if S.na else np.zeros(0)
    return answer["status"], np.array(answer["x"]).ravel(), alpha


def cone_rows(S, c):
    """The cones as rows A r <= b: -r_N <= 0, +-r_T - mu r_N <= c A."""
    n = S.n
    rows = np.zeros((3 * n, 2 * n))
    h = np.zeros(3 * n)
    for k in range(n):
        rows[3 * k, 2 * k] = -1.
        for j, sign in ((1, 1.), (2, -1.)):
            rows[3 * k + j, 2 * k + 1] = sign
            rows[3 * k + j, 2 * k] = -S.mu[k]
            h[3 * k + j] = c[k]
    return rows, h


def statics_admits(S, c):
    """Whether forces in the cones balance the floating blocks (an LP,
    HiGHS): the QP's feasibility, decided exactly (CVXOPT's QP does not
    always say 'infeasible')."""
    from scipy.optimize import linprog
    rows, h = cone_rows(S, c)
    if S.na == 0:
        return True
    lp = linprog(np.zeros(2 * S.n), A_ub=rows, b_ub=h, A_eq=S.G.T,
                 b_eq=-S.f, bounds=(None, None), method="highs")
    return lp.status == 0


def fixed_point(S, c, omega, iterations):
    """De Saxce's fixed point at cohesion c; (status, r, alpha, u,
    iterations, last change)."""
    shift = np.zeros(S.n)
    change = np.inf
    for it in range(1, iterations + 1):
        q_shifted = S.q.copy()
        q_shifted[0::2] += S.mu * shift
        status, r, alpha = solve_qp(S, q_shifted, c)
        # 'unknown': CVXOPT stopped short of its tolerances, the answer is
        # used (the final check decides); infeasibility ends the search.
        if "infeasible" in status:
            return status, r, alpha, None, it, change
        u = (S.W @ r + S.q + S.G @ alpha).reshape(-1, 2)
        new = (1. - omega) * shift + omega * np.abs(u[:, 1])
        change = np.abs(new - shift).max() / max(np.abs(u).max(), 1e-300)
        shift = new
        if change < SETTLED:
            break
    return "optimal", r, alpha, u, it, change


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("problem")
    parser.add_argument("--omega", type=float, default=0.5,
                        help="relaxation of the shift (1: none)")
    parser.add_argument("--iterations", type=int, default=500)
    args = parser.parse_args()
    p = load(args.problem)
    reason = unsupported(p)
    if reason:
        print("%s: not handled here (%s)" % (args.problem, reason))
        return 1
    S = Scaled(p)
    print("%s: %d pairs, %d rigid-body modes" % (
        os.path.basename(args.problem), S.n, S.na))
    c = S.c.copy()
    total = 0
    while True:
        if not statics_admits(S, c):
            print("verdict: no solution (statics admits no forces inside "
                  "the cones%s)" % (" once the joints that opened have "
                                   "lost their strength"
                                   if (c < S.c).any() else ""))
            return 2
        status, r, alpha, u, its, change = fixed_point(S, c, args.omega,
                                                       args.iterations)
        total += its
        if status != "optimal":
            print("QP %d: %s" % (total, status))
            print("verdict: no solution (statics admits no forces "
                  "inside the cones)")
            return 2
        R = r.reshape(-1, 2)
        # A gap that opens breaks the joint, also where the QP leaves it a
        # shear force (r_N = 0 with |r_T| <= c A: the cohesive part of
        # the cone, which an open joint no longer has).
        opened = [k for k in range(S.n) if c[k] > 0.
                  and u[k, 0] > TOLERANCE * np.abs(u).max()]
        print("fixed point: %d QPs, last change %.1e, %d joints break"
              % (its, change, len(opened)))
        if not opened:
            break
        c[opened] = 0.
    broken = [k for k in range(S.n) if c[k] == 0. and S.c[k] > 0.]
    states, violations, _ = check(S, R, alpha, broken=broken)
    worst = max(violations, key=violations.get)
    print("stick/slip/open %s, broken %d, QPs %d, worst violation %.1e (%s)"
          % ("/".join(str(collections.Counter(states)[s])
                      for s in ("stick", "slip", "open")),
             len(broken), total, violations[worst], worst))
    if violations[worst] < TOLERANCE:
        print("verdict: a solution exists")
        return 0
    print("verdict: undecided (the fixed point did not settle: change "
          "%.1e after %d QPs)" % (change, its))
    return 1


if __name__ == "__main__":
    sys.exit(main())
