#!/usr/bin/env python3
"""Seeded random pairs of blocks on inclines against their rigid-block limit.

Issue 27's must-show: two blocks side by side on an incline, a fixed base
(block 1) and two floating blocks resting on it, block 3 down-slope of
block 2, in two variants of the same drawn model:

  corner  the blocks touch along their common face (they share the corner
          on the base; the mesh is conforming there): interfaces
          'blocks 1:2; blocks 1:3; blocks 2:3';
  gap     the blocks stand GAP = 1 mm apart: 'blocks 1:2; blocks 1:3;
          boundaries 3:4' (boundary 3 block 3's face towards block 2, 4
          block 2's face towards block 3, paired across the gap with
          'Search distance' 1.5 mm), so that they touch only if they move.

Each model is drawn as scripts/random_inclines.py draws its blocks: sizes
L 0.5-4 m, H 0.3-3 m for each block, slope 0-30 deg, friction angle phi
10-45 deg of the base joints (both), phi23 10-45 deg of the 2:3 face,
cohesion 0-20 kPa on the base joints for one model in three (none on the
2:3 face; no tensile strength anywhere), a lateral pressure 0-10 kPa on
block 2's up-slope face for one model in two (ramped with the load
history), p = 1 or 2, 1 to 10 increments, the weight ramped over the
history or applied in full from the first increment. A model is kept if
it slides before it topples (below) and its limits lie in 0.2 < F < 5.
Elements of p/4 m (2 to 12 along each edge; at least 2 along every face,
so that the corner shared by three blocks leaves each interface a node
of its own, doc/jointed_rock.md), meshed by gmsh from a .geo the script
writes (structured quadrilaterals, the nodes of every face in contact
facing each other one to one).

The limit F: the largest factor by which every joint's strength (tan(phi),
c, sigma_t; here sigma_t = 0) can be divided such that rigid-block
equilibrium of blocks 2 and 3 still exists. It is computed here,
independently of mbfem, by a linear program (scipy.optimize.linprog,
HiGHS): the contact forces at the two end points of every face in contact
(base:2, base:3 and, where it is counted, 2:3), each a normal force
N >= -sigma_t A / 2 and a shear |T| <= (c A / 2 + tan(phi) N) / F (the
cohesion c A of a face split over its end points), and force and moment
equilibrium of each floating block under its weight and the lateral
pressure. For a straight face the end points give every admissible
distribution of tractions: any normal resultant N >= 0 acting within the
face, and a shear up to c A + tan(phi) N whose moment does not depend on
where along the face it acts. Feasibility is monotone in F; F is found by
bisection on feasibility (relative width 1e-10). The runs are made at
LAMBDAS = 0.95, 0.99 and 1.01 of F by dividing the strength (mu =
tan(phi) / (lambda F) on every face, also the 2:3 face, and c / (lambda
F)), the loads unchanged, as random_inclines.py does.

In the gap variant the 2:3 face is open in the reference state. The limit
without it is min(F2, F3), each block alone; with it (the 2:3 end points
at their places on either side of the gap), the LP of the corner variant
moved by 1 mm. The upper block can lean on the lower one only after it
has slid the 1 mm, which is a rigid motion of block 2 that the small-
displacement contact model allows (the gap closes), and only if the lower
block then holds: so the limit used is the one with the 2:3 face where
block 3 alone is stable at it (F3 >= F_with), else the one without. As
the lower block cannot be held by the upper one (no tension; the friction
of the 2:3 face lifts or presses it by at most tan(phi23) N23, against
the push N23), F_with <= F3 in practice and the limit used is F_with; the
line of each model prints both, F2 and F3, and says which is used. mbfem's
statics certificate counts the 2:3 pairs too (every candidate pair within
the search distance), so its limit is F_with as well.

Slides before it topples: each block alone has the normal resultant of its
weight (and block 2 of the lateral pressure) in the middle 70 % of its
base (as random_inclines.py), and the LP with the base forces restricted
to the middle 70 % of each base (end points at 15 % and 85 %) gives the
same limit (to 1e-6) as the full LP, in both variants: at the limit the
blocks slide, with the normal resultants away from the corners.

Check of the LP against closed forms (run at the start, its lines
printed; the script stops if any fails): (1) CHECKS single blocks drawn
as random_inclines.py draws them (the same LP code, one floating block):
F = (c A + W cos(theta) tan(phi)) / (W sin(theta) + P), random_inclines.py's
closed form; (2) each drawn model's gap variant without the 2:3 face,
blocks that do not interact: min(F2, F3) in that closed form; (3) the
corner variant with a frictionless 2:3 face (it passes only the push
N23 >= 0): F = min(F3, F23) with F23 = (c (L2 + L3) + (W2 + W3)
cos(theta) tan(phi)) / ((W2 + W3) sin(theta) + P), the two sliding
together; (4) toppling, the moment rows: a single block of c = 0 and
tan(phi) = 10 has a limit (above 1) where tan(theta) < L / H and none
(F = 0) where tan(theta) > L / H (1 % margins). Against mbfem: every run
that ends with a statics certificate (exit code 2 or 3) prints its
strength factor at the loads of its time t; lambda F times it is mbfem's
LP limit at t, which the summary compares with this LP at t. And every
run that converged: its final state is statically admissible with the
strength of the pairs it kept, so its factor must lie at or below this
LP's limit without the cohesion of the pairs it broke (its last pair
file); the summary says whether any lies above. This is also how a run
that converged at 1.01 is judged: where it broke fewer pairs than the
run at 0.95 that set the limit, its own limit is higher (the limit with
cohesion depends on which pairs the load history breaks).

Cohesion: a pair that opens breaks and loses its cohesion for good
(doc/state_iteration.md). As in random_inclines.py, the run at 0.95 of
the limit reads the pairs it broke from its last pair file; if it broke
any, the limit is computed again without the cohesion of those pairs
(the face's cohesive area reduced; where it acts along the face does not
matter, above) and the run at 0.95 repeated, up to MAX_ROUNDS rounds,
then 0.99 and 1.01 are run at the last limit. A run at 0.95 that fails
counts the pairs broken in its converged increments (its last pair file)
in the same way (those the failing increment broke are not written). The runs at 0.99 may break
more pairs than the one at 0.95: the line then says so (broken area per
run), and an exit code 3 there may be the model's (the certificate keeps
cohesion the elastic model has lost; doc/state_iteration.md, "An exit
code 3 can be the model's").

  python3 scripts/random_incline_pairs.py [--count 100] [--seed N]
      [--family issue27|broad] [--mbfem build/mbfem] [--work DIR]
      [--variants corner,gap] [--models 3,17] [--check-failures] [--test]

The seed is fresh at every run unless --seed (printed first; issue 27's
runs in doc/ used --seed 27, the default then). --family broad is issue
62's: the weight in full in increment 1 with the push zero there and
ramped after it (so increment 1 is gravity alone from the unloaded
state), 4 to 40 elements along each block's base joint (the other edges
meshed with the finer of the two sizes), cohesion up to 50 kPa in half
of the models, 1 to 10 increments (2 to 10 where pushed).

Writes the .geo, mesh and parameter file of every run into the work
folder (a fresh temporary one unless --work), runs mbfem on each, one at a
time, and prints one line per model and variant, the runs that ended with
exit code 3 (their increment and the first line of the message) and a
summary with the counts per variant and multiple of the limit (exit code:
0 converged, 2 certified no equilibrium, 3 not converged although
admissible, 4 no equilibrium along the mechanism, 1 other). The script
exits with 0 if issue 27's target is met (no exit code 3 at 0.95 and 0.99,
nothing converged at 1.01), else 1. --test leaves out the times, the
broken areas, the certificate's limits and the work folder, for a stored
output. --check-failures runs scripts/check_contact_problem_2d.py (an
exact mixed-integer check of the increment's contact problem, which every
exit code 3 writes; up to 300 s each) on each run below the limit that
ended with exit code 3 and prints its verdict: whether a solution of the elastic contact problem exists (then
the failure is the state iteration's) or none (the model's: cohesion that
the elastic blocks lose where pairs open, which the rigid-block LP and the
certificate count).
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

import numpy as np
from scipy.optimize import linprog

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from random_inclines import loads_2d  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTCOME = {0: "converged", 2: "certified-none", 3: "not-converged",
           4: "none-along-mechanism"}
UNIT_WEIGHT = 25e3
LAMBDAS = (0.95, 0.99, 1.01)
GAP = 1e-3
SEARCH = 1.5e-3
VARIANTS = ("corner", "gap")
MAX_ROUNDS = 4
CHECKS = 200
TOL = 1e-10
D, MARGIN = 1.0, 1.0   # depth of the base, base beyond the blocks


# ---------------------------------------------------------------------------
# Rigid-block statics
# ---------------------------------------------------------------------------

def lp_limit(blocks, faces):
    """The largest F such that forces exist with every face's tan(phi),
    c and sigma_t divided by F (0 if none for any F >= 1e-4, inf if some
    for F = 1e4).

    blocks: {name: dict(centroid=(x, y), force=(fx, fy), moment=m)}, the
      external loads of each floating block (moment about its centroid).
    faces: list of dict(mu=, cohesion=c A, tension=sigma_t A, n=(nx, ny),
      t=(tx, ty), points=[(block_a, (x, y), block_b or None, (x, y))]):
      at each point the force N n + T t acts on block_a at its point and
      the opposite one on block_b at its own (None: the fixed base).
    """
    names = sorted(blocks)
    row = {b: 3 * i for i, b in enumerate(names)}
    scale = max(1., max(math.hypot(*blocks[b]["force"]) for b in names))
    points = [(f, p) for f in faces for p in f["points"]]
    n_var = 2 * len(points)
    A_eq = np.zeros((3 * len(names), n_var))
    b_eq = np.zeros(3 * len(names))
    for b in names:
        fx, fy = blocks[b]["force"]
        b_eq[row[b]:row[b] + 3] = (-fx / scale, -fy / scale,
                                   -blocks[b]["moment"] / scale)

    def add(block, point, column, direction, sign):
        cx, cy = blocks[block]["centroid"]
        rx, ry = point[0] - cx, point[1] - cy
        dx, dy = sign * direction[0], sign * direction[1]
        A_eq[row[block], column] += dx
        A_eq[row[block] + 1, column] += dy
        A_eq[row[block] + 2, column] += rx * dy - ry * dx

    for k, (f, (block_a, point_a, block_b, point_b)) in enumerate(points):
        for column, direction in ((2 * k, f["n"]), (2 * k + 1, f["t"])):
            add(block_a, point_a, column, direction, 1.)
            if block_b is not None:
                add(block_b, point_b, column, direction, -1.)

    def feasible(F):
        A_ub = np.zeros((2 * len(points), n_var))
        b_ub = np.zeros(2 * len(points))
        bounds = []
        for k, (f, _) in enumerate(points):
            share = 1. / len(f["points"])
            for s in (0, 1):
                A_ub[2 * k + s, 2 * k] = -f["mu"] / F
                A_ub[2 * k + s, 2 * k + 1] = 1. if s == 0 else -1.
                b_ub[2 * k + s] = f["cohesion"] * share / F / scale
            bounds += [(-f["tension"] * share / F / scale, None),
                       (None, None)]
        r = linprog(np.zeros(n_var), A_ub=A_ub, b_ub=b_ub, A_eq=A_eq,
                    b_eq=b_eq, bounds=bounds, method="highs",
                    options=dict(primal_feasibility_tolerance=1e-10,
                                 dual_feasibility_tolerance=1e-10))
        if r.status not in (0, 2):
            raise RuntimeError("linprog: " + r.message)
        return r.status == 0

    lo, hi = 1e-4, 1e4
    if not feasible(lo):
        return 0.
    if feasible(hi):
        return math.inf
    while hi / lo - 1. > TOL:
        mid = math.sqrt(lo * hi)
        if feasible(mid):
            lo = mid
        else:
            hi = mid
    return lo


def loads(m, t=1.):
    """Weights W2, W3 and the lateral thrust P on block 2 at time t (the
    weight ramped with t if m["ramp"], the lateral pressure always)."""
    ramp = min(t, 1.) if m["ramp"] else 1.
    return (UNIT_WEIGHT * m["L2"] * m["H2"] * ramp,
            UNIT_WEIGHT * m["L3"] * m["H3"] * ramp, m["p_lat"] * m["H2"] * t)


def pair_statics(m, gap, contact23=True, which=(2, 3), shrink=0., t=1.,
                 kept=None, mu23=None):
    """The blocks and faces of the LP in the frame of the slope (x' up the
    slope, y' normal to it): block 3 at 0 <= x' <= L3, block 2 from
    L3 + gap, both on the base at y' = 0. 'which' the floating blocks
    counted; 'shrink' the fraction of each base left out at either end;
    'kept' the cohesive length of the bases {2: .., 3: ..} (default all);
    'mu23' the tan(phi) of the 2:3 face (default tan(phi23))."""
    th = math.radians(m["theta"])
    W2, W3, P = loads(m, t)
    x = {3: 0., 2: m["L3"] + gap}
    L = {2: m["L2"], 3: m["L3"]}
    H = {2: m["H2"], 3: m["H3"]}
    W = {2: W2, 3: W3}
    kept = kept or {2: L[2], 3: L[3]}
    mu = math.tan(math.radians(m["phi"]))
    blocks, faces = {}, []
    for b in which:
        cx, cy = x[b] + L[b] / 2, H[b] / 2
        fx, fy = -W[b] * math.sin(th), -W[b] * math.cos(th)
        moment = 0.
        if b == 2:   # the lateral thrust at mid-height of the up-slope face
            fx -= P
            moment += -(H[b] / 2 - cy) * (-P)
        blocks[b] = dict(centroid=(cx, cy), force=(fx, fy), moment=moment)
        ends = (x[b] + shrink * L[b], x[b] + (1. - shrink) * L[b])
        faces.append(dict(mu=mu, cohesion=m["c"] * kept[b], tension=0.,
                          n=(0., 1.), t=(1., 0.),
                          points=[(b, (e, 0.), None, None) for e in ends]))
    if contact23 and which == (2, 3):
        Hm = min(H[2], H[3])
        faces.append(dict(
            mu=(math.tan(math.radians(m["phi23"])) if mu23 is None
                else mu23),
            cohesion=0., tension=0., n=(1., 0.), t=(0., 1.),
            points=[(2, (x[2], y), 3, (x[3] + L[3], y)) for y in (0., Hm)]))
    return blocks, faces


def closed_form(W, theta, phi, c, area, P):
    """random_inclines.py's limit of one block sliding on one plane."""
    th = math.radians(theta)
    return ((c * area + W * math.cos(th) * math.tan(math.radians(phi)))
            / (W * math.sin(th) + P))


def limits(m, t=1., kept=None):
    """The limits of model m at time t: corner, gap with and without the
    2:3 face, each block alone, and the one used for the gap variant."""
    r = dict(corner=lp_limit(*pair_statics(m, 0., t=t, kept=kept)),
             gap_with=lp_limit(*pair_statics(m, GAP, t=t, kept=kept)),
             F2=lp_limit(*pair_statics(m, GAP, which=(2,), t=t, kept=kept)),
             F3=lp_limit(*pair_statics(m, GAP, which=(3,), t=t,
                                       kept=kept)))
    r["gap_without"] = min(r["F2"], r["F3"])
    r["gap_uses"] = "with" if r["F3"] >= r["gap_with"] * (1 - 1e-9) \
        else "without"
    r["gap"] = r["gap_with"] if r["gap_uses"] == "with" \
        else r["gap_without"]
    return r


# ---------------------------------------------------------------------------
# Models
# ---------------------------------------------------------------------------

def single_block(rng):
    """A block of random_inclines.py's draw (its rules: slides before it
    topples, 0.2 < F < 5), as a model of one floating block."""
    while True:
        b = dict(L=rng.uniform(0.5, 4.), H=rng.uniform(0.3, 3.),
                 theta=rng.uniform(0., 30.), phi=rng.uniform(10., 45.),
                 c=(rng.uniform(0., 20e3) if rng.random() < 1. / 3 else 0.),
                 p_lat=(rng.uniform(0., 10e3) if rng.random() < 0.5 else 0.))
        th = math.radians(b["theta"])
        W = UNIT_WEIGHT * b["L"] * b["H"]
        N, T = W * math.cos(th), W * math.sin(th) + b["p_lat"] * b["H"]
        if T <= 0.:
            continue
        x_n = (W * (b["L"] * math.cos(th) - b["H"] * math.sin(th)) / 2
               - b["p_lat"] * b["H"] * b["H"] / 2) / N
        if not 0.15 * b["L"] < x_n < 0.85 * b["L"]:
            continue
        b["F"] = closed_form(W, b["theta"], b["phi"], b["c"], b["L"],
                             b["p_lat"] * b["H"])
        if 0.2 < b["F"] < 5.:
            return b


def as_pair_model(b):
    """Block b as block 2 of a model whose block 3 is not counted."""
    return dict(L2=b["L"], H2=b["H"], L3=1., H3=1., theta=b["theta"],
                phi=b["phi"], phi23=30., c=b["c"], p_lat=b["p_lat"],
                ramp=False)


def resultant_inside(L, H, theta, P):
    """Whether the normal resultant of a block alone (weight, a thrust P
    at mid-height of its up-slope face) lies in the middle 70 % of its
    base."""
    th = math.radians(theta)
    W = UNIT_WEIGHT * L * H
    N = W * math.cos(th)
    x_n = (W * (L * math.cos(th) - H * math.sin(th)) / 2 - P * H / 2) / N
    return 0.15 * L < x_n < 0.85 * L


def draw_broad(rng):
    """The broad family's parameters (issue 62): gravity in full in the
    first increment, the push ramped from zero after it, 4 to 40 elements
    along each block's base joint, cohesion up to 50 kPa in half of the
    models."""
    pushed = rng.random() < 0.5
    return dict(L2=rng.uniform(0.5, 4.), H2=rng.uniform(0.3, 3.),
                L3=rng.uniform(0.5, 4.), H3=rng.uniform(0.3, 3.),
                theta=rng.uniform(0., 30.), phi=rng.uniform(10., 45.),
                phi23=rng.uniform(10., 45.),
                c=(rng.uniform(0., 50e3) if rng.random() < 0.5 else 0.),
                p_lat=rng.uniform(0., 10e3) if pushed else 0.,
                p=rng.choice([1, 2]),
                n_inc=rng.randint(2, 10) if pushed else rng.randint(1, 10),
                ramp=False, after=True,
                n2=rng.randint(4, 40), n3=rng.randint(4, 40))


def draw(rng, family="issue27"):
    """One model (both variants); resampled until it slides before it
    topples and its limits lie in (0.2, 5)."""
    while True:
        m = dict(L2=rng.uniform(0.5, 4.), H2=rng.uniform(0.3, 3.),
                 L3=rng.uniform(0.5, 4.), H3=rng.uniform(0.3, 3.),
                 theta=rng.uniform(0., 30.), phi=rng.uniform(10., 45.),
                 phi23=rng.uniform(10., 45.),
                 c=(rng.uniform(0., 20e3) if rng.random() < 1. / 3 else 0.),
                 p_lat=(rng.uniform(0., 10e3) if rng.random() < 0.5 else 0.),
                 p=rng.choice([1, 2]), n_inc=rng.randint(1, 10),
                 ramp=rng.random() < 0.5) if family == "issue27" \
            else draw_broad(rng)
        if not (resultant_inside(m["L2"], m["H2"], m["theta"],
                                 m["p_lat"] * m["H2"])
                and resultant_inside(m["L3"], m["H3"], m["theta"], 0.)):
            continue
        W2, W3, P = loads(m)
        F2 = closed_form(W2, m["theta"], m["phi"], m["c"], m["L2"], P)
        F3 = (closed_form(W3, m["theta"], m["phi"], m["c"], m["L3"], 0.)
              if m["theta"] > 0. else math.inf)
        # A cheap necessary condition before the LPs: the limit lies
        # between min(F2, F3) and F3.
        if not (min(F2, F3) < 5. and min(F2, F3) > 0.2 * 0.5):
            continue
        lim = limits(m)
        if not all(0.2 < lim[k] < 5. for k in ("corner", "gap",
                                                "gap_without")):
            continue
        if any(abs(lp_limit(*pair_statics(m, gap, shrink=0.15))
                   / lim[key] - 1.) > 1e-6
               for gap, key in ((0., "corner"), (GAP, "gap_with"))):
            continue
        m["limits"] = lim
        return m


def check_lp(rng, models):
    """The LP against the closed forms (docstring); lines, passed."""
    lines, passed = [], True
    worst = 0.
    for _ in range(CHECKS):
        b = single_block(rng)
        F = lp_limit(*pair_statics(as_pair_model(b), GAP, which=(2,)))
        worst = max(worst, abs(F / b["F"] - 1.))
    ok = worst < 1e-8
    passed &= ok
    lines.append("LP check 1, %d single blocks against the closed form: "
                 "largest relative difference %.1e%s"
                 % (CHECKS, worst, "" if ok else "  FAILED"))
    worst2 = worst3 = 0.
    n3 = 0
    for m in models:
        W2, W3, P = loads(m)
        F2 = closed_form(W2, m["theta"], m["phi"], m["c"], m["L2"], P)
        F3 = (closed_form(W3, m["theta"], m["phi"], m["c"], m["L3"], 0.)
              if m["theta"] > 0. else math.inf)
        worst2 = max(worst2, abs(m["limits"]["gap_without"]
                                 / min(F2, F3) - 1.))
        # (3) frictionless 2:3 face; only where that model slides too.
        full = lp_limit(*pair_statics(m, 0., mu23=0.))
        shrunk = lp_limit(*pair_statics(m, 0., mu23=0., shrink=0.15))
        if abs(shrunk / full - 1.) > 1e-6:
            continue
        F23 = ((m["c"] * (m["L2"] + m["L3"]) + (W2 + W3)
                * math.cos(math.radians(m["theta"]))
                * math.tan(math.radians(m["phi"])))
               / ((W2 + W3) * math.sin(math.radians(m["theta"])) + P))
        worst3 = max(worst3, abs(full / min(F3, F23) - 1.))
        n3 += 1
    ok = worst2 < 1e-8
    passed &= ok
    lines.append("LP check 2, %d models' gap variant without the 2:3 face "
                 "against min(F2, F3) in closed form: largest relative "
                 "difference %.1e%s" % (len(models), worst2,
                                        "" if ok else "  FAILED"))
    ok = worst3 < 1e-8 and n3 > 0
    passed &= ok
    lines.append("LP check 3, %d models' corner variant with a frictionless "
                 "2:3 face against min(F3, F23) in closed form: largest "
                 "relative difference %.1e%s"
                 % (n3, worst3, "" if ok else "  FAILED"))
    right = 0
    cases = 0
    for _ in range(CHECKS):
        L, H = rng.uniform(0.5, 4.), rng.uniform(0.3, 3.)
        theta = math.degrees(math.atan(L / H)) * rng.choice([0.99, 1.01])
        if theta >= 60.:
            continue
        cases += 1
        m = dict(L2=L, H2=H, L3=1., H3=1., theta=theta,
                 phi=math.degrees(math.atan(10.)), phi23=30., c=0.,
                 p_lat=0., ramp=False)
        F = lp_limit(*pair_statics(m, GAP, which=(2,)))
        stands = math.tan(math.radians(theta)) < L / H
        right += (F > 1.) if stands else (F == 0.)
    ok = right == cases
    passed &= ok
    lines.append("LP check 4, toppling of %d single blocks (tan(theta) = "
                 "0.99 or 1.01 L / H, tan(phi) = 10): %d right%s"
                 % (cases, right, "" if ok else "  FAILED"))
    return lines, passed


# ---------------------------------------------------------------------------
# Mesh and parameter file
# ---------------------------------------------------------------------------

def count(length, p, least=2):
    return max(least, min(12, int(round(4 * length / p))))


def write_geo(path, m, gap):
    """Structured quadrilaterals, every surface a rectangle of four lines,
    lines shared where rectangles meet (so that their nodes coincide);
    rotated by theta about the origin. Material ids 1 base, 2 block 2
    (up-slope), 3 block 3; boundary ids 1 the base's bottom, 2 block 2's
    up-slope face, and with a gap 3 block 3's face towards block 2 and 4
    block 2's face towards block 3 (up to the lower block's height)."""
    L2, H2, L3, H3, p = m["L2"], m["H2"], m["L3"], m["H3"], m["p"]
    Hm = min(H2, H3)
    x2 = L3 + gap
    out = ["// scripts/random_incline_pairs.py: %s" % os.path.basename(path)]
    points, lines, surfaces, physical = {}, {}, {1: [], 2: [], 3: []}, {}

    def point(x, y):
        key = (round(x, 12), round(y, 12))
        if key not in points:
            points[key] = len(points) + 1
            out.append("Point(%d) = {%.12g, %.12g, 0};"
                       % (points[key], x, y))
        return points[key]

    def line(a, b, n):
        if (b, a) in lines:
            return -lines[(b, a)]
        if (a, b) not in lines:
            lines[(a, b)] = len(lines) + 1
            out.append("Line(%d) = {%d, %d}; Transfinite Curve{%d} = %d;"
                       % (lines[(a, b)], a, b, lines[(a, b)], n + 1))
        return lines[(a, b)]

    def rect(x0, x1, y0, y1, nx, ny, block, tags=()):
        p00, p10 = point(x0, y0), point(x1, y0)
        p11, p01 = point(x1, y1), point(x0, y1)
        sides = dict(bottom=line(p00, p10, nx), right=line(p10, p11, ny),
                     top=line(p11, p01, nx), left=line(p01, p00, ny))
        s = len(surfaces[1]) + len(surfaces[2]) + len(surfaces[3]) + 1
        out.append("Curve Loop(%d) = {%d, %d, %d, %d}; Plane Surface(%d) "
                   "= {%d};" % (s, sides["bottom"], sides["right"],
                                sides["top"], sides["left"], s, s))
        surfaces[block].append(s)
        for side, tag in tags:
            physical.setdefault(tag, []).append(abs(sides[side]))

    if "n2" in m:
        # Broad family: the base joints' element counts drawn, the other
        # edges meshed with the finer of the two bases' element sizes.
        n2, n3 = m["n2"], m["n3"]
        h = min(L2 / n2, L3 / n3)

        def count(length, p, least=2, most=40):
            return max(least, min(most, int(round(length / h))))
    else:
        n2, n3 = count(L2, p), count(L3, p)
    nm, nd, nmarg = count(Hm, p), count(D, p, 1), count(MARGIN, p, 1)
    rect(0., L3, 0., Hm, n3, nm, 3, [("right", 3)] if gap else [])
    if H3 > Hm:
        rect(0., L3, Hm, H3, n3, count(H3 - Hm, p, 1), 3)
    rect(x2, x2 + L2, 0., Hm, n2, nm, 2,
         [("right", 2)] + ([("left", 4)] if gap else []))
    if H2 > Hm:
        rect(x2, x2 + L2, Hm, H2, n2, count(H2 - Hm, p, 1), 2,
             [("right", 2)])
    strips = [(-MARGIN, 0., nmarg), (0., L3, n3)]
    if gap:
        strips.append((L3, x2, 1))
    strips += [(x2, x2 + L2, n2), (x2 + L2, x2 + L2 + MARGIN, nmarg)]
    for x0, x1, n in strips:
        rect(x0, x1, -D, 0., n, nd, 1, [("bottom", 1)])
    every = surfaces[1] + surfaces[2] + surfaces[3]
    listed = ", ".join(map(str, every))
    out.append("Transfinite Surface{%s};" % listed)
    out.append("Recombine Surface{%s};" % listed)
    out.append("Rotate {{0, 0, 1}, {0, 0, 0}, %.12g * Pi / 180} "
               "{ Surface{%s}; }" % (m["theta"], listed))
    for block in (1, 2, 3):
        out.append("Physical Surface(%d) = {%s};"
                   % (block, ", ".join(map(str, surfaces[block]))))
    for tag in sorted(physical):
        out.append("Physical Curve(%d) = {%s};"
                   % (tag, ", ".join(map(str, physical[tag]))))
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def write_mesh(folder, i, m, variant):
    geo = os.path.join(folder, "pair%03d-%s.geo" % (i, variant))
    mesh = geo[:-4] + ".msh"
    if not os.path.exists(mesh):
        write_geo(geo, m, GAP if variant == "gap" else 0.)
        subprocess.run(["gmsh", "-2", "-format", "msh22", geo, "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
    return mesh


def loads_after(m):
    """The broad family's loads: the weight in full from the first
    increment, the lateral pressure zero in it and ramped after it (so the
    first increment is gravity alone from the unloaded state)."""
    th = math.radians(m["theta"])
    if m["p_lat"] == 0.:
        return """  set Prescribed displacement boundary ids = 1: xy
  set Gravity ramp time = 0
"""
    t1 = 1. / m["n_inc"]
    ramp = "max(0, (t - %.12g) / %.12g)" % (t1, 1. - t1)
    traction = "%.9g*%s; %.9g*%s" % (-m["p_lat"] * math.cos(th), ramp,
                                     -m["p_lat"] * math.sin(th), ramp)
    return """  set Prescribed displacement boundary ids = 1: xy
  set Traction boundary ids = 2
  set Gravity ramp time = 0
  subsection Traction
    set Function expression = %s
  end
""" % traction


def write_case(folder, name, mesh, m, variant, factor):
    mu = math.tan(math.radians(m["phi"])) / factor
    mu23 = math.tan(math.radians(m["phi23"])) / factor
    c = m["c"] / factor
    if variant == "corner":
        interfaces, search = "blocks 1:2; blocks 1:3; blocks 2:3", 0.
    else:
        interfaces, search = "blocks 1:2; blocks 1:3; boundaries 3:4", SEARCH
    prm = os.path.join(folder, name + ".prm")
    shown = {k: (round(v, 4) if isinstance(v, float) else v)
             for k, v in m.items() if k != "limits"}
    with open(prm, "w") as f:
        f.write("""# Random incline pair (scripts/random_incline_pairs.py), %s: %s
# Run at the strength factor F = %.9g.
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
%send
subsection Load history
  set Number of increments = %d
end
subsection Contact
  set Interfaces           = %s
  set Search distance      = %g
  set Friction coefficient = %.9g, %.9g, %.9g
  set Cohesion             = %.9g, %.9g, 0
end
subsection Output
  set Base name = pair
  set Directory = %s
  set Write VTU = false
end
""" % (variant, shown, factor, mesh, m["p"], UNIT_WEIGHT,
            loads_after(m) if m.get("after") else loads_2d(m), m["n_inc"],
            interfaces,
            search, mu, mu, mu23, c, c, name))
    return prm


# ---------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------

def broken_lengths(results):
    """Broken area per base interface {2: .., 3: ..} in the last pair
    file in 'results' (interfaces 'blocks 1:2' and 'blocks 1:3')."""
    files = sorted(glob.glob(os.path.join(results, "pair-pairs-*.csv")))
    broken = {2: 0., 3: 0.}
    if not files:
        return broken
    header = None
    for line in open(files[-1]):
        if line.startswith("#"):
            continue
        fields = line.strip().split(",")
        if header is None:
            header = fields
            continue
        row = dict(zip(header, fields))
        if row.get("broken") == "1":
            k = int(row["interface"])   # 1: blocks 1:2, 2: blocks 1:3
            if k in (1, 2):
                broken[1 + k] += float(row["area"])
    return broken


class Run:
    """One mbfem run: outcome, seconds, broken areas, the certificate's
    (strength factor, t) or None, the failing increment's message line."""

    def __init__(self, mbfem, folder, name, mesh, m, variant, factor):
        self.factor = factor
        prm = write_case(folder, name, mesh, m, variant, factor)
        results = os.path.join(folder, name)
        shutil.rmtree(results, ignore_errors=True)
        start = time.time()
        r = subprocess.run([mbfem, prm], cwd=folder, capture_output=True,
                           text=True)
        self.seconds = time.time() - start
        for suffix, text in ((".out", r.stdout), (".err", r.stderr)):
            with open(os.path.join(folder, name + suffix), "w") as f:
                f.write(text)
        self.code = r.returncode
        self.outcome = OUTCOME.get(r.returncode, "error")
        self.broken = broken_lengths(results)
        c = re.search(r"Statics certificate at t = ([0-9.e+-]+):", r.stderr)
        s = re.search(r"strength factor ([0-9.e+-]+)|divided by up to "
                      r"([0-9.e+-]+) \(strength factor\)", r.stderr)
        self.certificate = ((float(s.group(1) or s.group(2)),
                             float(c.group(1))) if c and s else None)
        self.message = ""
        first = ""
        for line in r.stderr.splitlines():
            if line.strip() and not first and line.strip() != "mbfem: error":
                first = line.strip()
            if line.strip().startswith("Load increment"):
                self.message = line.strip()
                break
        self.message = self.message or first
        self.methods = "/".join(str(len(re.findall(
            r"\((?:fast \d+, )?%s \d+\)" % method, r.stdout)))
            for method in ("load path", "semismooth Newton",
                           "load continuation"))
        self.prm = prm

    def describe(self, test):
        text = "%-14s" % self.outcome
        if test:
            return text.strip()
        if sum(self.broken.values()) > 0.:
            text += " broken %.3f m" % sum(self.broken.values())
        if self.certificate:
            text += " LP %.4f at t = %.4g" % (
                self.factor * self.certificate[0], self.certificate[1])
        if self.methods != "0/0/0":
            text += " P/N/C %s" % self.methods
        return text + " %.1f s" % self.seconds


def own_limit(m, variant, run):
    """The LP limit at t = 1 without the cohesion of the pairs that the
    run broke (its last pair file), with the 2:3 face (the gap variant's
    too: a converged state may have closed it). A converged run's forces
    are admissible for it, so its factor can never exceed this limit
    unless the LP is wrong."""
    kept = {b: max(0., m["L%d" % b] - run.broken[b]) for b in (2, 3)}
    return lp_limit(*pair_statics(m, 0. if variant == "corner" else GAP,
                                  kept=kept))


def check_problem(run, timeout=300):
    """The verdict of scripts/check_contact_problem_2d.py (an exact
    mixed-integer check) on the problem an exit code 3 wrote: a solution
    exists (the iteration's failure), none (the model's: the elastic
    blocks lose cohesion that the rigid-block LP counts) or undecided."""
    files = sorted(glob.glob(os.path.join(
        run.prm[:-4], "pair-failed-problem-*.json")))
    if not files:
        return "check: no problem file written"
    try:
        r = subprocess.run([sys.executable, os.path.join(
            SOURCE, "scripts", "check_contact_problem_2d.py"), files[-1]],
            capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "check: undecided in %d s" % timeout
    verdict = [line for line in r.stdout.splitlines()
               if line.startswith("verdict")]
    if not verdict:
        # Not a verdict: the check itself failed (its exit code 2 is then
        # also Python's for a script it cannot open).
        error = r.stderr.strip().splitlines()
        return "check did not run to a verdict (exit %d): %s" % (
            r.returncode, error[-1] if error else "no output")
    return "check (exit %d): %s" % (r.returncode, verdict[-1])


def campaign_variant(mbfem, work, i, m, variant):
    """Runs model i's variant at LAMBDAS of its limit (rounds for the
    broken pairs as in the docstring); (reference, rounds, {lambda: Run})."""
    mesh = write_mesh(work, i, m, variant)
    kept = {2: m["L2"], 3: m["L3"]}
    reference = m["limits"][variant]
    name = "pair%03d-%s-%%.2f" % (i, variant)
    for rounds in range(1, MAX_ROUNDS + 1):
        below = Run(mbfem, work, name % LAMBDAS[0], mesh, m, variant,
                    LAMBDAS[0] * reference)
        if m["c"] == 0. or rounds == MAX_ROUNDS:
            break
        now = {b: max(0., (m["L%d" % b]) - below.broken[b]) for b in (2, 3)}
        if all(now[b] >= kept[b] - 1e-9 for b in (2, 3)):
            break
        kept = {b: min(kept[b], now[b]) for b in (2, 3)}
        reference = limits(m, kept=kept)[variant]
    runs = {LAMBDAS[0]: below}
    for lam in LAMBDAS[1:]:
        runs[lam] = Run(mbfem, work, name % lam, mesh, m, variant,
                        lam * reference)
    return reference, rounds, kept, runs


def model_line(i, m, variant, reference, rounds, runs, test):
    lim = m["limits"]
    extra = ""
    if variant == "gap":
        extra = " (with 2:3 %.4f, without %.4f, F2 %.4f, F3 %s; uses %s)" % (
            lim["gap_with"], lim["gap_without"], lim["F2"],
            "%.4f" % lim["F3"] if lim["F3"] < math.inf else "inf",
            lim["gap_uses"])
    if rounds > 1 and not test:
        extra += " (round %d, unbroken %.4f)" % (rounds, lim[variant])
    return ("pair %3d %-6s L2=%.2f H2=%.2f L3=%.2f H3=%.2f theta=%5.2f "
            "phi=%4.1f phi23=%4.1f c=%5.0f p_lat=%5.0f p=%d inc=%2d "
            "ramp=%d%s F=%.4f%s | %s" % (
                i, variant, m["L2"], m["H2"], m["L3"], m["H3"], m["theta"],
                m["phi"], m["phi23"], m["c"], m["p_lat"], m["p"],
                m["n_inc"], m["ramp"],
                " n2=%d n3=%d" % (m["n2"], m["n3"]) if "n2" in m else "",
                lim[variant] if test else reference,
                extra, " | ".join("%.2f: %s" % (lam, runs[lam].describe(test))
                                  for lam in LAMBDAS)))


def summary(counts, variants, n_models, seconds):
    lines = ["", "summary (%d models%s): runs per variant and multiple of "
             "the limit" % (n_models, "" if seconds is None
                            else ", %.0f s" % seconds),
             "  %-7s %-6s %10s %15s %14s %6s" % (
                 "variant", "lambda", "converged", "certified-none",
                 "not-converged", "other")]
    passed = True
    for variant in variants:
        for lam in LAMBDAS:
            c = counts.get((variant, lam), {})
            other = sum(v for k, v in c.items()
                        if k not in ("converged", "certified-none",
                                     "not-converged"))
            lines.append("  %-7s %-6.2f %10d %15d %14d %6d" % (
                variant, lam, c.get("converged", 0),
                c.get("certified-none", 0), c.get("not-converged", 0),
                other))
            if lam < 1.:
                passed &= c.get("not-converged", 0) == 0
            else:
                passed &= c.get("converged", 0) == 0
    lines.append("issue 27's target (no exit code 3 at %.2f and %.2f, "
                 "nothing converged at %.2f): %s" % (
                     LAMBDAS[0], LAMBDAS[1], LAMBDAS[2],
                     "met" if passed else "not met"))
    return lines, passed


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=100)
    parser.add_argument("--seed", type=int, default=None,
                        help="the draw's seed (default: a fresh one, "
                        "printed; issue 27's stored runs used 27)")
    parser.add_argument("--family", choices=("issue27", "broad"),
                        default="issue27",
                        help="issue27: the weight ramped or in full, push "
                        "ramped from t = 0, 2-12 elements per edge, c up to "
                        "20 kPa in a third; broad (issue 62): the weight "
                        "in full in increment 1 with the push ramped after "
                        "it, 4-40 elements along each base joint, c up to "
                        "50 kPa in half")
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--work", default="")
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--models", default="",
                        help="run only these models (comma-separated "
                        "indices; the others are drawn, not run)")
    parser.add_argument("--check-failures", action="store_true",
                        help="decide the written problem of every exit "
                        "code 3 with scripts/check_contact_problem_2d.py")
    parser.add_argument("--test", action="store_true",
                        help="no times, no work folder (stored output)")
    args = parser.parse_args()
    if not os.access(args.mbfem, os.X_OK):
        sys.exit("--mbfem: %s is not an executable" % args.mbfem)
    variants = [v for v in args.variants.split(",") if v]
    if any(v not in VARIANTS for v in variants):
        sys.exit("--variants: corner, gap")
    work = args.work or tempfile.mkdtemp(prefix="mbfem-incline-pairs-")
    os.makedirs(work, exist_ok=True)
    if args.seed is None:
        args.seed = int.from_bytes(os.urandom(4), "little") % 1000000
    print("family %s, seed %d (--seed %d --family %s repeats this draw)"
          % (args.family, args.seed, args.seed, args.family), flush=True)
    rng = random.Random(args.seed)
    models = [draw(rng, args.family) for _ in range(args.count)]
    check_lines, checked = check_lp(random.Random(args.seed + 1), models)
    print("\n".join(check_lines), flush=True)
    if not checked:
        sys.exit("the LP does not reproduce its closed forms; no runs")
    counts, failures, beyond, compare, within = {}, [], [], [], []
    closing = {}
    start = time.time()
    n_models = 0
    for i, m in enumerate(models):
        if args.models and str(i) not in args.models.split(","):
            continue
        n_models += 1
        for variant in variants:
            reference, rounds, kept, runs = campaign_variant(
                args.mbfem, work, i, m, variant)
            # The limit of the blocks standing apart (gap variant).
            apart = (limits(m, kept=kept)["gap_without"]
                     if variant == "gap" else None)
            for lam, run in runs.items():
                c = counts.setdefault((variant, lam), {})
                c[run.outcome] = c.get(run.outcome, 0) + 1
                if apart is not None and lam < 1. and apart < run.factor:
                    c = closing.setdefault(lam, {})
                    c[run.outcome] = c.get(run.outcome, 0) + 1
                if run.outcome == "not-converged":
                    failures.append((i, variant, lam, run))
                if run.outcome == "converged":
                    own = own_limit(m, variant, run)
                    within.append((run.factor / own, i, variant, lam))
                    if lam > 1.:
                        beyond.append((i, variant, lam, run, own))
                if run.certificate:
                    # At the certificate's t, without the cohesion of the
                    # pairs broken by the last converged increment (those
                    # the failing one broke are not known here).
                    now = {b: min(kept[b], m["L%d" % b] - run.broken[b])
                           for b in (2, 3)}
                    key = "corner" if variant == "corner" else "gap_with"
                    mine = limits(m, t=run.certificate[1], kept=now)[key]
                    compare.append((i, variant, lam,
                                    run.factor * run.certificate[0], mine,
                                    m["c"] > 0.))
            print(model_line(i, m, variant, reference, rounds, runs,
                             args.test), flush=True)
    print("\nexit code 3 (%d):" % len(failures))
    verdicts = {}
    for i, variant, lam, run in failures:
        print("  pair %3d %-6s at %.2f (%s): %s" % (
            i, variant, lam, "c>0" if models[i]["c"] > 0. else "c=0",
            run.message))
        if args.check_failures and lam < 1.:
            verdict = check_problem(run)
            print("    %s" % verdict, flush=True)
            kind = ("model's (no solution)"
                    if "(exit 2): verdict: no solution" in verdict else
                    "solver's (a solution exists)"
                    if "(exit 0): verdict: a solution exists" in verdict
                    else "undecided")
            key = (kind, "below" if lam < 1. else "beyond")
            verdicts[key] = verdicts.get(key, 0) + 1
    if verdicts:
        print("  the checks: " + "; ".join(
            "%s %s the limit: %d" % (k + (verdicts[k],))
            for k in sorted(verdicts)))
    print("converged beyond the limit (%d):" % len(beyond))
    for i, variant, lam, run, own in beyond:
        print("  pair %3d %-6s at %.2f: run at F = %.6f; the LP without the "
              "cohesion of the %.3f m of pairs it broke gives %.6f, so the "
              "run is at %.4f of %s" % (
                  i, variant, lam, run.factor, sum(run.broken.values()),
                  own, run.factor / own,
                  "it: within its own limit" if run.factor <= own * (1 + 1e-6)
                  else "it: BEYOND its own limit"))
    if within:
        worst = max(within)
        print("every converged run against the LP without the cohesion of "
              "the pairs it broke (its state is admissible there): %d runs, "
              "%d above it; largest factor / limit %.6f (pair %d %s at "
              "%.2f)" % ((len(within),
                          sum(1 for w in within if w[0] > 1. + 1e-6))
                         + worst))
    for cohesive in (False, True):
        these = [c for c in compare if c[5] == cohesive]
        if not these or args.test:
            continue
        worst = max(these, key=lambda c: abs(c[3] / c[4] - 1.))
        print("mbfem's certificate against this LP, %s (%d runs, at the "
              "certificate's t): largest relative difference %.2e (pair %d "
              "%s at %.2f: %.6f against %.6f)%s"
              % (("c > 0" if cohesive else "c = 0", len(these),
                  abs(worst[3] / worst[4] - 1.)) + worst[:5]
                 + ("; with cohesion they differ where the failing "
                    "increment broke pairs, or where the certificate reads "
                    "the broken flags of the increment's start"
                    if cohesive else "",)))
    lines, passed = summary(counts, variants, n_models,
                            None if args.test else time.time() - start)
    for lam in sorted(closing):
        lines.append("gap variant at %.2f, runs where the blocks cannot "
                     "stand apart (block 2 must slide %g mm to lean on "
                     "block 3): %s" % (lam, GAP * 1e3, ", ".join(
                         "%s %d" % kv for kv in sorted(closing[lam].items()))))
    print("\n".join(lines))
    if not args.test:
        print("work folder:", work)
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
