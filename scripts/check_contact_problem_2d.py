#!/usr/bin/python3
"""Does a 2D contact problem written by mbfem have a solution? An
independent check of an increment's problem (doc/contact_problems.md):
u = W r + q + G alpha, G^T r + f = 0, and per pair the Mohr-Coulomb joint
law (stick / slip / open) with cohesion c A and no tension.

  /usr/bin/python3 scripts/check_contact_problem_2d.py PROBLEM.json

Two methods:
 1. An exact mixed-integer formulation of the joint law (binaries per pair:
    open, slip+ (u_T >= 0, r_T = -(cA + mu r_N)), slip- (u_T <= 0,
    r_T = +(cA + mu r_N)), else stick; big-M bounds R on forces, U on
    displacements), solved with scipy's HiGHS MILP (python3-scipy). The
    force bound is rigorous (every r_N <= sum r_N); the displacement bound
    is tried at 10, 100 and 1000 mm, so "no solution" means none with
    displacements below 1 m. Where none exists, a second MILP finds the
    least equilibrium defect that would make one.
 2. Lemke's algorithm (lexicographic, dense) on the 2D Coulomb LCP, with
    the cohesion of open pairs removed by a fixed point on the broken set.
Every candidate is checked against the joint law.

Exit code: 0 a solution exists (printed), 2 the MILP proves there is none
(within the displacement bound), 1 anything else: undecided (HiGHS's
time limit of 600 s per MILP: 406 pairs of parameters/dam_foundation.prm
were not decided in it) or a model it does not handle (3D, tension
limits, tensile slip, held directions, tied pairs).
Written to decide whether mbfem's exit code 3 ("the state iteration gave
up although statics admits forces") is the solver's failure or the
model's: the rigid-block statics LP counts cohesion at pairs that the
elastic blocks cannot keep closed.
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from read_contact_problem import load  # noqa: E402

FS, US = 1e6, 1e-3          # force unit MN, displacement unit mm


class Scaled:
    def __init__(self, p):
        assert p["dimension"] == 2
        self.p = p
        self.n, self.na = p["n_pairs"], p["n_alpha"]
        self.W = p["Wm"] * FS / US
        self.G = p["Gm"].copy()
        self.q = p["q"] / US
        self.f = p["f"] / FS
        self.mu = np.where(p["tensile_slip"] > 0, p["mu"], p["mu"])
        self.c = p["cohesion"] / FS
        self.t = p["tension"] / FS
        self.held = np.array(p["held"], dtype=bool).reshape(self.n, 2)


# ----------------------------------------------------------------- checking
def check(S, r, alpha, tol_u=1e-9, tol_f=1e-9, broken=None):
    """r [MN] (n,2), alpha [mm]; classifies each pair and returns states and
    the largest violation of each condition (forces relative to max|r|,
    displacements relative to the largest term of u)."""
    n = S.n
    rr = r.reshape(-1)
    terms = [S.W @ rr, S.q, S.G @ alpha]
    u = (terms[0] + terms[1] + terms[2]).reshape(n, 2)
    dscale = max(np.abs(t).max() for t in terms)
    fscale = max(np.abs(rr).max(), np.abs(S.f).max())
    r = rr.reshape(n, 2)
    c = S.c.copy()
    if broken is not None:
        c[list(broken)] = 0.
    viol = dict(equilibrium=np.abs(S.G.T @ rr + S.f).max() / fscale)
    states = []
    for k in range(n):
        rn, rt, un, ut = r[k, 0], r[k, 1], u[k, 0], u[k, 1]
        lim = c[k] + S.mu[k] * max(rn, 0.)
        if np.abs(r[k]).max() <= tol_f * fscale and un > tol_u * dscale:
            st = "open"
            v = {"open r=0": np.abs(r[k]).max() / fscale,
                 "open u_N>=0": max(-un, 0) / dscale}
        elif abs(ut) <= tol_u * dscale:
            st = "stick"
            v = {"stick u=0": np.abs(u[k]).max() / dscale,
                 "stick cone": max(abs(rt) - lim, 0) / fscale,
                 "r_N>=-tension": max(-rn - S.t[k], 0) / fscale}
        else:
            st = "slip"
            v = {"slip u_N=0": abs(un) / dscale,
                 "slip |r_T|=limit": abs(abs(rt) - lim) / fscale,
                 "slip r_T against u_T": max(rt * np.sign(ut), 0) / fscale,
                 "r_N>=-tension": max(-rn - S.t[k], 0) / fscale}
        for key, val in v.items():
            viol[key] = max(viol.get(key, 0.), val)
        states.append(st)
    return states, viol, u


# --------------------------------------------------------------------- MILP
def milp_solve(S, U=1000., R=20., eq_slack=False, start=None, quiet=False):
    from scipy.optimize import milp, LinearConstraint, Bounds
    from scipy.sparse import lil_matrix
    n, na, inf = S.n, S.na, np.inf
    ir, ia = 0, 2 * n
    iu = ia + na
    io = iu + 2 * n
    isp, isn = io + n, io + 2 * n
    ie = io + 3 * n
    N = ie + 2 * na
    rows, lo, hi = [], [], []

    def add(d, l, h):
        rows.append(d); lo.append(l); hi.append(h)
    for i in range(2 * n):                      # u - W r - G alpha = q
        d = {iu + i: 1.0}
        for j in range(2 * n):
            d[ir + j] = -S.W[i, j]
        for j in range(na):
            d[ia + j] = -S.G[i, j]
        add(d, S.q[i], S.q[i])
    for j in range(na):                         # G^T r (+ e) = -f
        d = {ir + i: S.G[i, j] for i in range(2 * n)}
        if eq_slack:
            d[ie + j] = 1; d[ie + na + j] = -1
        add(d, -S.f[j], -S.f[j])
    for k in range(n):
        rn, rt, un, ut = ir + 2 * k, ir + 2 * k + 1, iu + 2 * k, iu + 2 * k + 1
        o, sp, sn = io + k, isp + k, isn + k
        c, mu, t = S.c[k], S.mu[k], S.t[k]
        add({o: 1, sp: 1, sn: 1}, -inf, 1)
        add({un: 1}, 0, inf)                    # gap >= 0
        add({un: 1, o: -U}, -inf, 0)            # closed: u_N = 0
        add({rn: 1, o: -t}, -t, inf)            # closed: r_N >= -tension; open: r_N >= 0
        add({rn: 1, o: R}, -inf, R)             # open: r_N <= 0
        # |r_T| <= cA + mu r_N (valid for every state; tension > 0 with
        # r_N < 0 would need max(r_N, 0): not modelled, asserted below)
        add({rt: 1, rn: -mu}, -inf, c)
        add({rt: 1, rn: mu}, -c, inf)
        add({rt: 1, o: R}, -inf, R)             # open: r_T = 0
        add({rt: 1, o: -R}, -R, inf)
        add({ut: 1, o: -U, sp: -U}, -inf, 0)    # u_T <= 0 unless open / slip+
        add({ut: 1, o: U, sn: U}, 0, inf)       # u_T >= 0 unless open / slip-
        M2 = 3 * R
        add({rt: 1, rn: mu, sp: M2}, -inf, -c + M2)   # slip+: r_T = -(cA+mu rN)
        add({rt: 1, rn: -mu, sn: -M2}, c - M2, inf)   # slip-: r_T = +(cA+mu rN)
        for d in range(2):
            if S.held[k, d]:
                add({ir + 2 * k + d: 1}, 0, 0)
    assert np.all(S.t == 0), "tension > 0: the cone's max(r_N,0) is not modelled"
    A = lil_matrix((len(rows), N))
    for i, d in enumerate(rows):
        for j, v in d.items():
            A[i, j] = v
    lb, ub = np.full(N, -inf), np.full(N, inf)
    lb[ir:ia], ub[ir:ia] = -R, R
    lb[iu:io], ub[iu:io] = -U, U
    lb[io:ie], ub[io:ie] = 0, 1
    lb[ie:], ub[ie:] = 0, 100
    integ = np.zeros(N); integ[io:ie] = 1
    obj = np.zeros(N)
    if eq_slack:
        obj[ie:] = 1
    elif start is not None:                      # fewest changes of state
        for k, s in enumerate(start):
            obj[io + k] = -1 if s == "open" else 1
            w = -1 if s == "slip" else 1
            obj[isp + k] += w; obj[isn + k] += w
    res = milp(obj, constraints=LinearConstraint(A.tocsr(), lo, hi),
               integrality=integ, bounds=Bounds(lb, ub),
               options=dict(disp=False, time_limit=600, mip_rel_gap=0))
    out = dict(status=res.status, message=res.message)
    if res.x is not None:
        x = res.x
        out["states"] = ["open" if x[io + k] > .5 else "slip+" if x[isp + k] > .5
                         else "slip-" if x[isn + k] > .5 else "stick" for k in range(n)]
        out["r"] = x[ir:ia].reshape(n, 2)
        out["alpha"] = x[ia:iu]
        out["e"] = x[ie:ie + na] - x[ie + na:]
    return out


# -------------------------------------------------------------------- Lemke
def lemke(M, q, maxit=5000):
    """Lemke's complementary pivoting with covering vector 1 and the
    lexicographic ratio test. Returns (z, w, status, pivots)."""
    n = len(q)
    if q.min() >= 0:
        return np.zeros(n), q.copy(), "trivial", 0
    T = np.hstack([np.eye(n), -M, -np.ones((n, 1)), q[:, None]]).astype(float)
    basis = list(range(n))                       # w_i is variable i, z_i is n+i, z0 is 2n
    enter = 2 * n
    # first pivot: row of the most negative q (lexicographic among ties)
    row = int(np.argmin(q))
    it = 0
    while True:
        it += 1
        piv = T[row, enter]
        T[row] /= piv
        for i in range(n):
            if i != row and T[i, enter] != 0:
                T[i] -= T[i, enter] * T[row]
        leave = basis[row]
        basis[row] = enter
        if leave == 2 * n:
            status = "solution"
            break
        if it >= maxit:
            status = "maxit"
            break
        enter = leave + n if leave < n else leave - n
        col = T[:, enter]
        cand = np.where(col > 1e-12 * max(1., np.abs(col).max()))[0]
        if cand.size == 0:
            status = "ray"
            break
        # z0 leaves on a tie
        ratios = T[cand, -1] / col[cand]
        rmin = ratios.min()
        tie = cand[ratios <= rmin + 1e-12 * max(1., abs(rmin))]
        if 2 * n in [basis[i] for i in tie]:
            row = [i for i in tie if basis[i] == 2 * n][0]
        else:
            for j in range(n):                   # lexicographic: columns of B^-1
                if tie.size == 1:
                    break
                v = T[tie, j] / col[tie]
                tie = tie[v <= v.min() + 1e-14]
            row = int(tie[0])
    x = np.zeros(2 * n + 1)
    for i, b in enumerate(basis):
        x[b] = T[i, -1]
    return x[n:2 * n], x[:n], status, it


def lcp_matrix(S, broken):
    n, na = S.n, S.na
    N = 4 * n + 2 * na
    Rm = np.zeros((2 * n, N))                    # r = Rm z
    for k in range(n):
        Rm[2 * k, k] = 1
        Rm[2 * k + 1, n + k] = 1
        Rm[2 * k + 1, 2 * n + k] = -1
    Am = np.zeros((na, N))                       # alpha = Am z
    Am[:, 4 * n:4 * n + na] = np.eye(na)
    Am[:, 4 * n + na:] = -np.eye(na)
    Um = S.W @ Rm + S.G @ Am                     # u = Um z + q
    M = np.zeros((N, N)); qq = np.zeros(N)
    c = S.c.copy(); c[list(broken)] = 0.
    for k in range(n):
        M[k] = Um[2 * k]; qq[k] = S.q[2 * k]                      # u_N
        M[n + k] = Um[2 * k + 1]; M[n + k, 3 * n + k] += 1        # s + u_T
        qq[n + k] = S.q[2 * k + 1]
        M[2 * n + k] = -Um[2 * k + 1]; M[2 * n + k, 3 * n + k] += 1  # s - u_T
        qq[2 * n + k] = -S.q[2 * k + 1]
        M[3 * n + k, k] = S.mu[k]; M[3 * n + k, n + k] = -1; M[3 * n + k, 2 * n + k] = -1
        qq[3 * n + k] = c[k]
    GR = S.G.T @ Rm
    M[4 * n:4 * n + na] = -GR; qq[4 * n:4 * n + na] = -S.f
    M[4 * n + na:] = GR; qq[4 * n + na:] = S.f
    return M, qq, Rm, Am


def lemke_fixed_point(S, maxouter=30, quiet=False):
    broken, seen, log = set(), [], []
    for outer in range(maxouter):
        M, qq, Rm, Am = lcp_matrix(S, broken)
        z, w, status, piv = lemke(M, qq)
        entry = dict(broken=sorted(broken), status=status, pivots=piv)
        if status != "solution":
            log.append(entry)
            return None, log
        r = (Rm @ z).reshape(S.n, 2); alpha = Am @ z
        states, viol, u = check(S, r, alpha, broken=broken)
        # every pair with a gap: it carries no shear, so it loses its cohesion
        dscale = max(np.abs(S.W @ r.reshape(-1)).max(), np.abs(S.q).max())
        opened = {k for k in range(S.n) if u[k, 0] > 1e-9 * dscale}
        entry.update(states=states, opened=sorted(opened),
                     worst=max(viol.values()))
        log.append(entry)
        if opened == broken or (opened <= broken and all(
                S.c[k] == 0 for k in broken - opened)):
            return (r, alpha, states, viol), log
        key = frozenset(opened)
        if key in seen:
            log.append(dict(cycle=True))
            return None, log
        seen.append(key)
        broken = opened
    return None, log


# ------------------------------------------------------------------- report
def summary(states):
    c = {s: [k for k, x in enumerate(states) if x.startswith(s)]
         for s in ("stick", "slip", "open")}
    return "stick/slip/open %d/%d/%d, slip %s, open %s" % (
        len(c["stick"]), len(c["slip"]), len(c["open"]), c["slip"], c["open"])


def unsupported(p):
    """What of the problem the MILP does not model, or ''."""
    if p["dimension"] != 2:
        return "3D"
    if np.any(p["tension"] > 0):
        return "tension limits"
    if np.any(p["tensile_slip"] > 0):
        return "tensile slip"
    if np.any(p["held"]):
        return "held directions"
    if any(p["tied"]):
        return "tied pairs"
    return ""


def run(path, quiet=False):
    """Prints the checks; returns 0 (a solution), 2 (none) or 1."""
    p = load(path)
    reason = unsupported(p)
    if reason:
        print("%s: not handled here (%s)" % (os.path.basename(path), reason))
        return 1
    S = Scaled(p)
    print("== %s: %d pairs, %d modes, solved=%s, start %s" % (
        os.path.basename(path), S.n, S.na, p["solved"], summary(p["state"])))
    print("   cohesion cA [kN] %s; tension max %g; broken %d" % (
        np.round(p["cohesion"] / 1e3, 1)[:3], p["tension"].max(), int(sum(p["broken"]))))
    # sum r_T = f_x and sum r_N = -f_y (G's translation columns), so the
    # shear the closed pairs can carry is at most mu V + sum_closed cA
    if np.all(S.mu == S.mu[0]) and S.na == 3:
        area = np.array(p["area"])
        need = (S.f[0] - S.mu[0] * -S.f[1]) / (S.c / area).max()
        print("   H = %.4g MN, mu V = %.4g MN, sum cA = %.4g MN: a solution needs"
              " closed area >= %.3f of %.1f" % (S.f[0], -S.mu[0] * S.f[1], S.c.sum(),
              need, area.sum()))
    verdict = 2
    for U in (10., 100., 1000.):
        out = milp_solve(S, U=U, start=p["state"])
        print("-- MILP (U = %g mm): %s" % (U, out["message"][:70]))
        if "r" not in out and out["status"] != 2:
            # a time limit without a solution proves nothing (status 2 is
            # scipy's "infeasible")
            print("verdict: undecided (the MILP stopped before it decided)")
            return 1
        if "r" in out:
            states, viol, u = check(S, out["r"], out["alpha"])
            print("   states", summary(out["states"]))
            print("   check:", {k: float("%.2e" % v) for k, v in viol.items()})
            verdict = 0
            changed = [k for k in range(S.n)
                       if out["states"][k].rstrip("+-") != p["state"][k]]
            print("   changed from start:", changed)
            if p["solved"]:
                print("   max |r - r_mbfem| / max|r| = %.2e" % (
                    np.abs(out["r"].reshape(-1) * FS - p["r"]).max() / np.abs(p["r"]).max()))
            break
    else:
        out = milp_solve(S, U=1000., eq_slack=True)
        print("-- MILP, least l1 equilibrium defect e (G^T r + f = e): %s" % out["message"][:40])
        if "r" in out:
            print("   e = %s N (N, N, scaled moment)  states %s" % (
                np.round(out["e"] * FS, 1), summary(out["states"])))
            st = out["states"]
            closed = [k for k in range(S.n) if st[k] != "open"]
            cap = S.c[closed].sum() + S.mu[0] * (-S.f[1])
            print("   horizontal load %.4g MN; sliding capacity mu V + sum_closed cA = %.4g MN"
                  % (S.f[0], cap))
    # Lemke with the broken-set fixed point
    res, log = lemke_fixed_point(S)
    print("-- Lemke / broken-set fixed point:")
    for e in log:
        if "cycle" in e:
            print("   cycle in the broken set")
            continue
        print("   broken %s: %s after %d pivots%s" % (
            e["broken"], e["status"], e["pivots"],
            "" if "states" not in e else ", " + summary(e["states"]) +
            ", worst check %.1e" % e["worst"]))
    if res is not None:
        r, alpha, states, viol = res
        print("   solution:", summary(states))
        print("   check:", {k: float("%.2e" % v) for k, v in viol.items()})
    print("verdict: %s" % ("a solution exists" if verdict == 0 else
                           "no solution with displacements below 1 m"))
    return verdict


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(run(sys.argv[1]))
