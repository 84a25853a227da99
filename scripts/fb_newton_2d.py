#!/usr/bin/python3
"""Semismooth Newton methods for a 2D contact problem written by mbfem
(doc/contact_problems.md): u = W r + q + G alpha, G^T r + f = 0, per pair
Coulomb's law with cohesion c A, no tension. A prototype (issue 62) to find
out whether the increments on which every state method of mbfem gives up
(exit code 3, statics admitting forces) have a solution.

  /usr/bin/python3 scripts/fb_newton_2d.py PROBLEM.json
      [--method ac|fb|smooth|all|mu] [--iterations 300] [--start lp|zero]
      [--factor 2.5] [--steps 400] [--log]

Methods (all in MN and mm, unknowns r and alpha, the equalities
G^T r + f = 0 among the equations):
 ac      Alart and Curnier's function, generalised Newton, Armijo line search
         on 1/2 |F|^2 (Siconos' fc2d NSN_AC with the floating blocks'
         equilibrium added). F is piecewise affine here.
 fb      Fischer-Burmeister on the 2D Coulomb LCP (r_T = b+ - b-, slip rate
         lambda: r_N _|_ u_N, b+ _|_ lambda + u_T, b- _|_ lambda - u_T,
         lambda _|_ mu r_N + c A - b+ - b-), alpha free: De Luca, Facchinei
         and Kanzow's semismooth Newton with a gradient step where the
         Newton direction does not descend.
 smooth  the same with the smoothed function sqrt(a^2 + b^2 + 2 eps^2) -
         a - b, eps driven from 1 to 0 (a path-following regularisation).
 mu      continuation in the friction: a solution at --factor times every
         mu (De Saxce's QPs, then ac), then Keller's pseudo-arclength
         continuation of ac's equations in (r, alpha, t), mu = t mu_problem,
         through turning points, down to t = 1. It ends 'solved', or on a
         'ray' (forces fixed, rigid-body amplitudes growing without bound at
         a fixed t: a collapse mechanism of the non-associated law, whose
         closed pairs and rigid-body direction it prints).

On tests/failures/toppling_column_drawn_14 (increment 1, 93 pairs): ac,
fb and smooth stall (|F| about 1e-2, every pair moving); mu follows the
branch from 2.5 mu through a turning point at mu = 1.088 to a ray at
mu = 1.11844: every block turning about its downslope base corner (stuck),
sliding on its neighbour at one point. That is Goodman and Bray's
toppling limit of the same column (tan(phi) = 1.118438, their sliding
check left out), above the problem's mu = 0.762.

Every answer is checked with scripts/check_contact_problem_2d.py's check()
(violations below 1e-7). Exit code 0: a solution found and checked; 1: none
found (which proves nothing).

Cohesion: a pair that opens keeps its c A here (no breaking); the answer is
checked with the pairs that opened counted as broken, as
desaxce_fixed_point_2d.py does. The problems it was written for have c = 0.
"""
import argparse
import collections
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_contact_problem_2d import Scaled, check, unsupported  # noqa: E402
from read_contact_problem import load  # noqa: E402

TOLERANCE = 1e-7


def states_summary(S, r, alpha):
    u = (S.W @ r.reshape(-1) + S.q + S.G @ alpha).reshape(-1, 2)
    dscale = max(np.abs(u).max(), 1e-300)
    opened = [k for k in range(S.n) if S.c[k] > 0
              and u[k, 0] > TOLERANCE * dscale]
    states, viol, u = check(S, r.reshape(-1, 2), alpha, broken=opened)
    return states, viol, u


# ----------------------------------------------------------- Alart-Curnier
class AlartCurnier:
    def __init__(self, S, rho=None):
        self.S = S
        n = S.n
        d = np.diag(S.W)
        self.rho = 1.0 / np.maximum(d[0::2], d[1::2]) if rho is None else rho
        self.A = np.hstack([S.W, S.G])          # u = A x + q
        self.size = 2 * n + S.na

    def residual(self, x, jac=False):
        S, n = self.S, self.S.n
        r = x[:2 * n]
        u = self.A @ x + S.q
        rN, rT, uN, uT = r[0::2], r[1::2], u[0::2], u[1::2]
        rho = self.rho
        dN = rN - rho * uN
        pN = np.maximum(0., dN)
        g = S.mu * pN + S.c
        dT = rT - rho * uT
        F = np.empty(self.size)
        F[0:2 * n:2] = rN - pN
        F[1:2 * n:2] = rT - np.clip(dT, -g, g)
        F[2 * n:] = S.G.T @ r + S.f
        if not jac:
            return F
        J = np.zeros((self.size, self.size))
        for k in range(n):
            iN, iT = 2 * k, 2 * k + 1
            if dN[k] > 0:
                J[iN] = rho[k] * self.A[iN]
            else:
                J[iN, iN] = 1.
            if abs(dT[k]) < g[k]:
                J[iT] = rho[k] * self.A[iT]
            else:
                J[iT, iT] = 1.
                if dN[k] > 0:
                    s = np.sign(dT[k])
                    # - s mu d(dN) with d(dN) = e_N - rho A_N
                    J[iT, iN] -= s * S.mu[k]
                    J[iT] += s * S.mu[k] * rho[k] * self.A[iN]
        J[2 * n:, :2 * n] = S.G.T
        return F, J

    def split(self, x):
        n = self.S.n
        return x[:2 * n].reshape(n, 2), x[2 * n:]


def newton_ac(S, x0, iterations, log):
    """Generalised Newton on Alart and Curnier's F, Armijo on 1/2 |F|^2;
    where the Newton step does not decrease it, a Levenberg-Marquardt
    step (J^T J + nu I) d = -J^T F, nu raised until it does."""
    P = AlartCurnier(S)
    x = x0.copy()
    F, J = P.residual(x, jac=True)
    psi = 0.5 * F @ F
    nu = 1e-8
    for it in range(1, iterations + 1):
        kind = "N"
        try:
            d = np.linalg.solve(J, -F)
        except np.linalg.LinAlgError:
            d = None
        t = 1.
        accepted = False
        if d is not None and np.all(np.isfinite(d)):
            while t > 1e-6:
                Fn = P.residual(x + t * d)
                if 0.5 * Fn @ Fn <= (1 - 2e-4 * t) * psi:
                    accepted = True
                    break
                t *= 0.5
        if not accepted:
            kind = "LM"
            JTJ, g = J.T @ J, J.T @ F
            scale = np.trace(JTJ) / len(x)
            while nu < 1e12:
                d = np.linalg.solve(JTJ + nu * scale * np.eye(len(x)), -g)
                Fn = P.residual(x + d)
                if 0.5 * Fn @ Fn < psi + 1e-4 * (g @ d):
                    accepted = True
                    nu = max(nu / 10, 1e-12)
                    break
                nu *= 10
            t = 1.
        if not accepted:
            break
        x = x + t * d
        F, J = P.residual(x, jac=True)
        psi = 0.5 * F @ F
        if log:
            print("  ac %3d %s step %.2e |F| %.3e" % (it, kind, t,
                                                      np.sqrt(2 * psi)))
        if np.sqrt(2 * psi) < 1e-13 * max(1., np.abs(S.f).max()):
            break
    r, alpha = P.split(x)
    return r, alpha, it, np.sqrt(2 * psi)


# ------------------------------------------------- Fischer-Burmeister (LCP)
class FBLCP:
    """z = (r_N, b+, b-, lambda) >= 0 (4n), alpha free (na)."""

    def __init__(self, S):
        self.S = S
        n, na = S.n, S.na
        N = 4 * n + na
        Rm = np.zeros((2 * n, N))                # r = Rm x
        for k in range(n):
            Rm[2 * k, k] = 1
            Rm[2 * k + 1, n + k] = 1
            Rm[2 * k + 1, 2 * n + k] = -1
        Am = np.zeros((na, N))
        Am[:, 4 * n:] = np.eye(na)
        Um = S.W @ Rm + S.G @ Am                 # u = Um x + q
        M = np.zeros((4 * n, N))
        b = np.zeros(4 * n)
        for k in range(n):
            M[k] = Um[2 * k]; b[k] = S.q[2 * k]
            M[n + k] = Um[2 * k + 1]; M[n + k, 3 * n + k] += 1
            b[n + k] = S.q[2 * k + 1]
            M[2 * n + k] = -Um[2 * k + 1]; M[2 * n + k, 3 * n + k] += 1
            b[2 * n + k] = -S.q[2 * k + 1]
            M[3 * n + k, k] = S.mu[k]; M[3 * n + k, n + k] = -1
            M[3 * n + k, 2 * n + k] = -1
            b[3 * n + k] = S.c[k]
        self.M, self.b, self.Rm, self.Am = M, b, Rm, Am
        self.E = S.G.T @ Rm                      # equalities: E x + f = 0
        self.m, self.N = 4 * n, N

    def residual(self, x, eps=0., jac=False):
        m = self.m
        a = x[:m]
        w = self.M @ x + self.b
        root = np.sqrt(a * a + w * w + 2 * eps * eps)
        F = np.concatenate([root - a - w, self.E @ x + self.S.f])
        if not jac:
            return F
        safe = np.where(root > 0, root, 1.)
        da = np.where(root > 0, a / safe, 1 / np.sqrt(2)) - 1
        dw = np.where(root > 0, w / safe, 1 / np.sqrt(2)) - 1
        J = np.zeros((self.N, self.N))
        J[:m] = dw[:, None] * self.M
        J[np.arange(m), np.arange(m)] += da
        J[m:] = self.E
        return F, J

    def split(self, x):
        return (self.Rm @ x).reshape(-1, 2), self.Am @ x

    def from_r(self, r, alpha):
        n = self.S.n
        r = r.reshape(n, 2)
        x = np.zeros(self.N)
        x[:n] = np.maximum(r[:, 0], 0)
        x[n:2 * n] = np.maximum(r[:, 1], 0)
        x[2 * n:3 * n] = np.maximum(-r[:, 1], 0)
        x[4 * n:] = alpha
        return x


def newton_fb(P, x0, iterations, log, eps_schedule=None, name="fb"):
    """DFK: Newton direction where it descends enough, else the gradient;
    Armijo on Psi. eps_schedule: the smoothing, one value per stage."""
    x = x0.copy()
    stages = eps_schedule if eps_schedule is not None else [0.]
    total = 0
    for eps in stages:
        last = eps == stages[-1]
        for it in range(iterations):
            total += 1
            F, J = P.residual(x, eps, jac=True)
            psi = 0.5 * F @ F
            grad = J.T @ F
            try:
                d = np.linalg.solve(J, -F)
                ok = grad @ d <= -1e-10 * (d @ d) ** 1.05
            except np.linalg.LinAlgError:
                ok = False
            if not ok:
                d = -grad
            t = 1.
            while t > 1e-12:
                Fn = P.residual(x + t * d, eps)
                if 0.5 * Fn @ Fn <= psi + 1e-4 * t * (grad @ d):
                    break
                t *= 0.5
            x = x + t * d
            res = np.sqrt(2 * (0.5 * Fn @ Fn))
            if log and (it % 10 == 0 or res < 1e-12):
                print("  %s eps %.1e it %3d %s step %.1e |F| %.3e" % (
                    name, eps, it, "N" if ok else "g", t, res))
            # stage tolerance: tight at the last stage
            if res < (1e-13 if last else max(1e-2 * eps, 1e-13)):
                break
            if t <= 1e-12:
                break
    F = P.residual(x, 0.)
    r, alpha = P.split(x)
    return r, alpha, total, np.linalg.norm(F)


# ------------------------------------------- continuation in the friction
def with_mu(S, mu):
    import copy
    T = copy.copy(S)
    T.mu = np.full(S.n, mu) if np.isscalar(mu) else mu
    return T


def ac_with_mu(S, y):
    """Alart and Curnier's F and its Jacobian in (r, alpha, t), the
    friction coefficients being t times the problem's."""
    n, t = S.n, y[-1]
    T = with_mu(S, t * S.mu)
    P = AlartCurnier(T)
    x = y[:-1]
    F, J = P.residual(x, jac=True)
    u = P.A @ x + S.q
    dN = x[0:2 * n:2] - P.rho * u[0::2]
    pN = np.maximum(0., dN)
    dT = x[1:2 * n:2] - P.rho * u[1::2]
    slip = (np.abs(dT) >= T.mu * pN + S.c) & (dN > 0)
    dt = np.zeros(len(x))
    dt[1:2 * n:2] = np.where(slip, -np.sign(dT) * S.mu * pN, 0.)
    return F, np.hstack([J, dt[:, None]])


def start_at(S, factor, log):
    """A solution at friction factor * mu: De Saxce's fixed point (QPs,
    desaxce_fixed_point_2d.py) to 1e-5, then Alart and Curnier's Newton."""
    import desaxce_fixed_point_2d as ds
    T = with_mu(S, factor * S.mu)
    shift = np.zeros(S.n)
    for it in range(400):
        qs = T.q.copy()
        qs[0::2] += T.mu * shift
        status, r, alpha = ds.solve_qp(T, qs, T.c)
        u = (T.W @ r + T.q + T.G @ alpha).reshape(-1, 2)
        new = 0.5 * shift + 0.5 * np.abs(u[:, 1])
        change = np.abs(new - shift).max() / max(np.abs(u).max(), 1e-300)
        shift = new
        if change < 1e-5:
            break
    r, alpha, its, res = newton_ac(T, np.concatenate([r, alpha]), 100, False)
    ok = max(states_summary(T, r, alpha)[1].values()) < TOLERANCE
    if log:
        print("  start at %g mu: %d QPs, %d Newton iterations, %s" % (
            factor, it + 1, its, "solved" if ok else "not solved"))
    return ok, np.concatenate([r.reshape(-1), alpha, [factor]])


def continuation_mu(S, factor, steps, log):
    """Pseudo-arclength continuation (Keller) of Alart and Curnier's
    equations in (r, alpha, t), mu = t * mu_problem, from t = factor down
    to t = 1, through turning points. Returns (status, y, history):
    status 'solved' (t = 1 reached and the answer solved there),
    'ray' (the forces settle while the displacements grow without bound
    at a fixed t: a mechanism of the non-associated law), 'stalled'."""
    ok, y = start_at(S, factor, log)
    if not ok:
        return "no start", y, [], None
    n = S.n
    F, J = ac_with_mu(S, y)
    tangent = np.linalg.svd(J)[2][-1]
    if tangent[-1] > 0:
        tangent = -tangent
    h, history, turns = 0.05, [], []
    for step in range(steps):
        pred = y + h * tangent
        z, converged = pred.copy(), False
        for _ in range(12):
            F, J = ac_with_mu(S, z)
            A = np.vstack([J, tangent])
            b = np.concatenate([F, [tangent @ (z - pred)]])
            try:
                z = z - np.linalg.solve(A, b)
            except np.linalg.LinAlgError:
                break
            if np.linalg.norm(ac_with_mu(S, z)[0]) < 1e-12:
                converged = True
                break
        if not converged or np.linalg.norm(z - y) > 2 * h:
            h /= 2
            if h < 1e-12:
                return "stalled", y, history, tangent
            continue
        F, J = ac_with_mu(S, z)
        new = np.linalg.svd(J)[2][-1]
        if new @ tangent < 0:
            new = -new
        if np.sign(new[-1]) != np.sign(tangent[-1]) and abs(new[-1]) > 1e-6:
            turns.append(z[-1])
            if log:
                print("  turning point at mu = %.6g (t = %.6f)"
                      % (z[-1] * S.mu[0], z[-1]))
        y, tangent, h = z, new, min(1.3 * h, 2.)
        r, alpha = y[:2 * n].reshape(n, 2), y[2 * n:-1]
        history.append((y[-1], np.abs(r).max(), np.abs(alpha).max()))
        if log and step % 20 == 0:
            T = with_mu(S, y[-1] * S.mu)
            st = collections.Counter(states_summary(T, r, alpha)[0])
            print("  %4d t %.6f stick/slip/open %d/%d/%d max|r| %.4g MN "
                  "max|alpha| %.4g" % (step, y[-1], st["stick"], st["slip"],
                                       st["open"], np.abs(r).max(),
                                       np.abs(alpha).max()))
        if y[-1] <= 1.:
            T = with_mu(S, S.mu)
            r, alpha, its, res = newton_ac(T, y[:-1], 50, False)
            y = np.concatenate([r.reshape(-1), alpha, [1.]])
            return "solved", y, history, tangent
        # a ray: over the last 40 steps t and the forces stationary (1e-7,
        # 1e-6 relative) while the rigid-body amplitudes grew
        if len(history) > 40:
            t0, r0, a0 = history[-40]
            if (abs(y[-1] - t0) < 1e-7 * y[-1]
                    and abs(np.abs(r).max() - r0) < 1e-6 * r0
                    and np.abs(alpha).max() > 1.1 * a0):
                return "ray", y, history, tangent
    return "stalled", y, history, tangent



# ------------------------------------------------------------------ starts
def lp_start(S):
    """Forces strictly inside the cones with G^T r + f = 0: maximise the
    smallest margin mu r_N - |r_T| relative to r_N (an LP, HiGHS)."""
    from scipy.optimize import linprog
    n = S.n
    # variables r (2n), t; maximise t with mu r_N - |r_T| >= t, r_N >= t
    N = 2 * n + 1
    rows, h = [], []
    for k in range(n):
        for s in (1., -1.):
            a = np.zeros(N); a[2 * k + 1] = s; a[2 * k] = -S.mu[k]; a[-1] = 1
            rows.append(a); h.append(S.c[k])
        a = np.zeros(N); a[2 * k] = -1; a[-1] = 1
        rows.append(a); h.append(0.)
    c = np.zeros(N); c[-1] = -1
    Aeq = np.hstack([S.G.T, np.zeros((S.na, 1))])
    lp = linprog(c, A_ub=np.array(rows), b_ub=np.array(h), A_eq=Aeq,
                 b_eq=-S.f, bounds=[(None, None)] * 2 * n + [(None, 1.)],
                 method="highs")
    r = lp.x[:2 * n]
    # alpha: least squares of u = 0 (a stick start)
    alpha = np.linalg.lstsq(S.G, -(S.W @ r + S.q), rcond=None)[0]
    return r, alpha, lp.x[-1]


def report(S, name, r, alpha, its, res, seconds):
    states, viol, u = states_summary(S, r, alpha)
    worst = max(viol, key=viol.get)
    cnt = collections.Counter(states)
    print("%-7s %4d iterations, %.1f s, |F| %.2e: stick/slip/open %d/%d/%d, "
          "worst violation %.1e (%s)" % (name, its, seconds, res,
                                         cnt["stick"], cnt["slip"],
                                         cnt["open"], viol[worst], worst))
    return viol[worst] < TOLERANCE, states, u


def run_continuation(S, args):
    t0 = time.time()
    status, y, history, tangent = continuation_mu(S, args.factor, args.steps,
                                                  args.log)
    n = S.n
    r, alpha = y[:2 * n].reshape(n, 2), y[2 * n:-1]
    print("continuation in mu from %g mu: %s at mu = %.6g (t = %.6f) after "
          "%d steps, %.0f s" % (args.factor, status, y[-1] * S.mu[0], y[-1],
                                len(history), time.time() - t0))
    if status == "solved":
        ok, states, u = report(S, "mu", r, alpha, len(history), 0.,
                               time.time() - t0)
        return 0 if ok else 1
    if status == "ray":
        T = with_mu(S, y[-1] * S.mu)
        states, viol, u = states_summary(T, r, alpha)
        d = tangent[2 * n:-1] / np.abs(tangent[2 * n:-1]).max()
        dr = np.abs(tangent[:2 * n]).max() / np.abs(tangent[2 * n:-1]).max()
        print("  the forces settle (|dr|/|dalpha| along the ray %.1e), the "
              "rigid-body amplitudes grow; stick/slip/open %s" % (
                  dr, "/".join(str(states.count(s))
                               for s in ("stick", "slip", "open"))))
        print("  closed pairs on the ray: stick %s, slip %s" % (
            [k for k in range(n) if states[k] == "stick"],
            [k for k in range(n) if states[k] == "slip"]))
        print("  the ray's alpha (normalised, per floating mode): %s"
              % np.array2string(d, precision=3))
    return 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("problem")
    ap.add_argument("--method", default="all",
                    choices=("ac", "fb", "smooth", "all", "mu"))
    ap.add_argument("--factor", type=float, default=2.5,
                    help="--method mu: start at this multiple of mu")
    ap.add_argument("--steps", type=int, default=400)
    ap.add_argument("--iterations", type=int, default=300)
    ap.add_argument("--start", default="lp", choices=("lp", "zero"))
    ap.add_argument("--log", action="store_true")
    ap.add_argument("--save", help="write r [N] and alpha to this .npz")
    args = ap.parse_args()
    p = load(args.problem)
    reason = unsupported(p)
    if reason:
        print("not handled here (%s)" % reason)
        return 1
    S = Scaled(p)
    print("%s: %d pairs, %d rigid-body modes" % (
        os.path.basename(args.problem), S.n, S.na))
    if args.method == "mu":
        return run_continuation(S, args)
    if args.start == "lp":
        r0, a0, margin = lp_start(S)
        print("start: LP forces, smallest margin %.3e MN" % margin)
    else:
        r0, a0 = np.zeros(2 * S.n), np.zeros(S.na)
    methods = ("ac", "fb", "smooth") if args.method == "all" else (args.method,)
    found = None
    for m in methods:
        t0 = time.time()
        if m == "ac":
            r, alpha, its, res = newton_ac(S, np.concatenate([r0, a0]),
                                           args.iterations, args.log)
        else:
            P = FBLCP(S)
            x0 = P.from_r(r0, a0)
            sched = None if m == "fb" else [10. ** -k for k in range(0, 13)] + [0.]
            r, alpha, its, res = newton_fb(P, x0, args.iterations, args.log,
                                           sched, m)
        ok, states, u = report(S, m, r, alpha, its, res, time.time() - t0)
        if ok and found is None:
            found = (m, r, alpha, states, u)
    if found is None:
        print("verdict: no solution found")
        return 1
    m, r, alpha, states, u = found
    print("verdict: a solution exists (%s)" % m)
    if args.save:
        np.savez(args.save, r=r.reshape(-1) * 1e6, alpha=alpha,
                 states=np.array(states), u=u.reshape(-1) * 1e-3)
    return 0


if __name__ == "__main__":
    sys.exit(main())
