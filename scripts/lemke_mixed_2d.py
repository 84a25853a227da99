#!/usr/bin/python3
"""Lemke's method on a 2D contact problem written by mbfem, as a mixed LCP:
the floating amplitudes alpha free and basic throughout, the floating
blocks' equilibrium G^T r + f = 0 as equalities, instead of the split
alpha = alpha+ - alpha- (two inequalities) that mbfem's LemkeMethod and
scripts/check_contact_problem_2d.py use. Written to tell whether a
secondary ray comes from that split (a free variable's two halves
growing together) or from the problem.

  /usr/bin/python3 scripts/lemke_mixed_2d.py PROBLEM.json

Start: each alpha enters the basis on the complementarity row with its
largest coefficient, then each equilibrium row's slack leaves for the
force whose complement that pivot made non-basic; then Lemke's method
with the artificial variable on the complementarity rows only, the
alpha rows never leaving. No cohesion breaking (use it on problems
without cohesion). Prints how it ended, the pivots, and for a solution
the states and the largest violation of the joint law
(check_contact_problem_2d.check). Exit code 0 for a solution, 1 else.

Measured (doc/state_iteration.md, "Lemke's method"): model 40 of the
two-block campaign, a solution in 62 pivots with the states of
mbfem's Lemke; Goodman and Bray's column at 0.985 of its limit, a ray
after 698 pivots, as with the split.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_contact_problem_2d as C  # noqa: E402
from read_contact_problem import load  # noqa: E402


def mixed_lemke(MCC, MCA, MEC, qC, qE, maxit=50000, tol=1e-12):
    """w = MCC z + MCA a + qC >= 0 _|_ z >= 0, 0 = MEC z + qE, a free.
    Returns (status, pivots, z, a)."""
    nc, na = len(qC), len(qE)
    m = nc + na
    # Columns: slacks (m), z (nc), a (na), z0, rhs.
    A = np.zeros((m, m + nc + na + 2))
    A[:, :m] = np.eye(m)
    A[:nc, m:m + nc] = -MCC
    A[:nc, m + nc:m + nc + na] = -MCA
    A[nc:, m:m + nc] = -MEC
    A[:, -1] = np.concatenate([qC, qE])
    z0 = m + nc + na
    basis = list(range(m))

    def pivot(r, c):
        A[r] /= A[r, c]
        col = A[:, c].copy()
        col[r] = 0.
        A[:] -= np.outer(col, A[r])
        basis[r] = c

    freed = []
    for a in range(na):
        c = m + nc + a
        r = max((i for i in range(nc) if basis[i] < nc),
                key=lambda i: abs(A[i, c]))
        freed.append(basis[r])
        pivot(r, c)
    for e in range(na):
        r = basis.index(nc + e)
        c = max((m + i for i in freed if m + i not in basis),
                key=lambda j: abs(A[r, j]))
        pivot(r, c)

    def rows():
        return [i for i in range(m) if not m + nc <= basis[i] < z0]

    A[:, z0] = 0.
    A[rows(), z0] = -1.
    r = min(rows(), key=lambda i: A[i, -1])
    status, it, enter = "trivial", 0, z0
    if A[r, -1] < 0.:
        while True:
            it += 1
            leave = basis[r]
            pivot(r, enter)
            if leave == z0:
                status = "solution"
                break
            if it >= maxit:
                status = "pivot limit"
                break
            enter = m + leave if leave < nc else leave - m
            col, cr = A[:, enter], rows()
            big = max(1., np.abs(col[cr]).max())
            cand = [i for i in cr if col[i] > tol * big]
            if not cand:
                status = "ray"
                break
            ratios = [A[i, -1] / col[i] for i in cand]
            least = min(ratios)
            tie = [i for i, x in zip(cand, ratios)
                   if x <= least + 1e-12 * max(1., abs(least))]
            r = next((i for i in tie if basis[i] == z0), tie[0])
    z, a = np.zeros(nc), np.zeros(na)
    for i, b in enumerate(basis):
        if m <= b < m + nc:
            z[b - m] = A[i, -1]
        elif m + nc <= b < z0:
            a[b - m - nc] = A[i, -1]
    return status, it, z, a


def main(path):
    S = C.Scaled(load(path))
    M, qq, Rm, Am = C.lcp_matrix(S, set())
    n, na = S.n, S.na
    nc = 4 * n
    scale = np.abs(qq).max()
    status, pivots, z, a = mixed_lemke(
        M[:nc, :nc], M[:nc, nc:nc + na], M[nc + na:, :nc],
        qq[:nc] / scale, qq[nc + na:] / scale)
    print("%s after %d pivots" % (status, pivots))
    if status not in ("solution", "trivial"):
        return 1
    full = np.concatenate([z, a, np.zeros(na)]) * scale
    r, alpha = (Rm @ full).reshape(n, 2), Am @ full
    states, violation, _ = C.check(S, r, alpha)
    print(C.summary(states), "; largest violation %.2g"
          % max(violation.values()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
