#!/usr/bin/env python3
"""Seeded random toppling columns on stepped bases against their rigid-block
limit (issue 62, part 1).

Issue 62 asks the project's random campaigns to find what held-out cases
find, among them toppling columns of 5 to 20 blocks on stepped bases (a
held-out one, Hoek and Bray's 16 blocks with 'Interfaces = all', c = 0,
p = 1, ended with exit code 3 at 0.95 of its limit). This script draws
such columns with a fresh seed every run (printed first; --seed repeats a
draw) and runs each at LAMBDAS = 0.95, 0.99 and 1.01 of its limit.

The model (Goodman and Bray's geometry, scripts/goodman_bray.py, but the
blocks touching): n blocks of width dx, numbered from the toe (block 1,
material id 2) up the slope (block n, material id n + 1), each standing on
its own tread of a fixed base (material id 1, held at its bottom,
boundary id 1). The treads dip psi_p; the blocks' sides are normal to the
treads; each tread lies b above the one downslope, so that the line of the
steps' corners (the base angle) dips psi_b = psi_p + atan(b / dx). Built
in the frame of the treads (x' down the dip, y' normal to the treads; the
toe block on 0 <= x' <= dx, block k on -(k-1) dx <= x' <= -(k-2) dx, its
tread at y' = (k - 1) b), then rotated by -psi_p. There are no gaps: each
block touches its tread, the riser of the step upslope of it (the b lowest
metres of its upslope face; the top block has none, the base upslope of it
is flat) and its neighbours along the faces they share (from the upper
block's tread to the top of the shorter block). The mesh is conforming on
every one of these faces and the parameter file says 'Interfaces = all':
one interface per pair of neighbouring bodies (base:block, the tread and
the riser together; block:block), every one with the same friction angle
phi (and cohesion c, if any), as the held-out column was declared.

Drawn per model (random.Random(seed), one model after the other):
n 5 to 20 (5 to 14 where p = 2, which costs more), dx 0.5 to 2 m, psi_b
10 to 40 deg, psi_p from max(0, psi_b - 25) to min(30, psi_b - 3) deg
(so the step height b = dx tan(psi_b - psi_p), 0.05 to 0.47 dx), the
heights either Goodman and Bray's regular slope (rising linearly from
1-2 dx at the toe to 3-6 dx at a crest block drawn in the middle third,
then falling linearly to 1-2.5 dx at the top) or each 1 to 6 dx at
random, phi 20 to 45 deg on every joint, c = 0 (with --cohesive-share s,
a share s of the models gets c up to 5 kPa), unit weight 25 kN/m^3, E
1e9 to 1e10 Pa (log-uniform), nu 0.2 to 0.3, p = 1 or 2, 2 to 4 (p = 2)
or 3 to 6 (p = 1) elements across a block, the weight in full from the
first increment ('Gravity ramp time = 0') over 1 to 3 increments. Tops
closer than 0.3 element to a tread level or another top are moved onto it
(the mesh would need slivers there), before the limit is computed. A model
is kept if 0.25 < F_norise < 5 and the limit friction tan(phi) / F_norise
lies in (0.05, 2) (F_norise below), and HiGHS gives a verdict on every LP
of both bisections; else it is drawn again.

The limit F: the largest factor by which every joint's tan(phi) (and c)
can be divided such that rigid-block equilibrium of the n floating blocks
still exists. Computed here independently of mbfem by a linear program
(scipy.optimize.linprog, HiGHS; lp_limit() of scripts/random_incline_pairs.py,
the same LP): at each end point of every face in contact (both ends of
each tread, of each riser, of each face between neighbours) a normal force
N >= 0 and a shear |T| <= (c A / 2 + tan(phi) N) / F, and force and
moment equilibrium of every block under its weight. For a straight face
its end points give every admissible distribution of tractions (any
normal resultant within the face, the shear's moment independent of where
it acts), so the LP admits every mechanism of the rigid blocks, not one
assumed. F by bisection on feasibility (relative width 1e-10). The runs
divide tan(phi) (and c) by lambda F on every joint, the loads unchanged,
as random_incline_pairs.py does: mu = tan(phi) / (lambda F).

Two limits, because of the risers. The LP is solved twice: F_norise with
the treads and the faces between blocks only (the faces issue 62 names,
and Goodman and Bray's geometry), F with the risers too (the geometry
mbfem meshes). mbfem's own statics lies between them: at the concave
corner of each step (the block's upslope foot) tread and riser share a
node, and mbfem makes one pair there whose normal bisects the two faces'
(measured in the problem files: (0.92, 0.39) against the tread's (0.37,
0.93) and the riser's (0.93, -0.37) at psi_p = 21.9 deg), so that pair's
cone holds neither face's normal force where mu < 1; the riser's other
nodes (its top, a p = 2 midside node, more cells) pair with the riser's
normal. So the certificate's limit depends on the riser's mesh: on seed
1's first draws it was F_norise to 5 digits with p = 1 and one cell on
the riser, and 0.88520 between F_norise 0.87218 and F 0.89243 with
p = 2. The runs below the limit are therefore made at 0.95 and 0.99 of
F_norise (under mbfem's pairs' limit, but for that corner pair), the run
above it at 1.01 of F (above any subset of the continuum's contacts, so
statics must admit nothing: every one of mbfem's pairs lies on a face
the LP with risers counts, with a cone inside that face's). Where the
risers do not help (F = F_norise, models that slide), both are the same.
Every run that ends with a certificate prints its limit (strength factor
times the run's factor) beside the two.

Checks of the LP (printed at the start): on the project's column
(meshes/toppling_column.geo, 0.1 mm gaps, no riser in contact) the same
LP with the interblock forces only at the top of the shorter block must
give Goodman and Bray's limit (scripts/goodman_bray.py, 2.039446) and with
them anywhere on the faces goodman_bray.py --rigid's 2.301105 (mbfem's
certificate's 2.30110, doc/jointed_rock.md). Per model the line prints
three limits: F (the LP of the model mbfem solves, risers in contact),
F_norise (without the risers, the geometry Goodman and Bray assume) and
F_GB (Goodman and Bray's limit equilibrium, goodman_bray.analyse(), at the
tan(phi) drawn; '<tan(phi)' where its limit friction is tan(phi) >= 1,
beyond its sliding formula's range). The LP
admits every mechanism, Goodman and Bray assume one (forces at the top
of the shorter block, full friction on every face), so F_norise >= F_GB
and F >= F_norise (more contacts can only help).

Verdicts: mbfem exits 0 when every increment converged, 2 when its statics
certificate proves no equilibrium exists, 3 when statics admits forces but
no state was found, 4 when no equilibrium exists along the statics
mechanism; a run longer than --timeout seconds is killed ('timeout'). Below
the limit the right answer is 0, above it 2. A failure is any other
answer: exit code 3 below the limit (the defect the campaign looks for),
0 above it (this LP or mbfem wrong), timeouts and errors. Exit code 2
below the limit means mbfem's certificate found no forces where this LP
did (mbfem's certificate and this LP disagree, or the increment broke
cohesion). --keep DIR copies the .geo, .msh, .prm and the screen output
(.out, .err) of every failure there, as test inputs, and the contact
problem its failed increment wrote (DIR/NAME/*-failed-problem-*).

  /usr/bin/python3 scripts/random_toppling_columns.py [--count 40]
      [--seed N] [--models 3,17] [--mbfem build/mbfem] [--work DIR]
      [--keep DIR] [--timeout 300] [--budget S] [--cohesive-share 0]
      [--flat] [--dry-run]

Runs one mbfem at a time with OPENBLAS_NUM_THREADS=1 (and the binary's
folder on LD_LIBRARY_PATH, for a copied build). --budget S starts no new
model after S seconds of runs. --dry-run draws the models, prints their
lines and writes their meshes, but runs nothing. --flat runs the same
draw with the steps removed (b = 0: every block on one plane, no risers,
no step edges), to tell whether a failure needs the steps.
"""

import argparse
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from random_incline_pairs import lp_limit  # noqa: E402
import goodman_bray  # noqa: E402

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNIT_WEIGHT = 25e3
LAMBDAS = (0.95, 0.99, 1.01)
OUTCOME = {0: "converged", 2: "certified-none", 3: "not-converged",
           4: "none-along-mechanism"}
COLUMNS = ("converged", "certified-none", "not-converged",
           "none-along-mechanism", "timeout", "error")


# ---------------------------------------------------------------------------
# Rigid-block statics
# ---------------------------------------------------------------------------

def column_statics(m, risers=True, gb_point=False, gap=0.):
    """lp_limit()'s blocks and faces of column m in the frame of the
    treads. risers: count the riser upslope of each block (its b lowest
    metres of upslope face against the base); gb_point: the force between
    neighbours only at the top of the shorter block (Goodman and Bray's
    point), else at both ends of the face in contact; gap: the blocks
    stand this far apart (x' of block k: -k (dx + gap), 0-based)."""
    dx, b, psi = m["dx"], m["b"], math.radians(m["psi_p"])
    mu = math.tan(math.radians(m["phi"]))
    ys = m["heights"]
    n = len(ys)
    xs = [-k * (dx + gap) for k in range(n)]
    tops = [k * b + ys[k] for k in range(n)]
    blocks, faces = {}, []
    for k in range(n):
        W = UNIT_WEIGHT * dx * ys[k]
        blocks[k] = dict(centroid=(xs[k] + 0.5 * dx, k * b + 0.5 * ys[k]),
                         force=(W * math.sin(psi), -W * math.cos(psi)),
                         moment=0.)
        faces.append(dict(mu=mu, cohesion=m["c"] * dx, tension=0.,
                          n=(0., 1.), t=(1., 0.),
                          points=[(k, (x, k * b), None, None)
                                  for x in (xs[k], xs[k] + dx)]))
        if k + 1 < n and risers and b > 0.:
            faces.append(dict(mu=mu, cohesion=m["c"] * b, tension=0.,
                              n=(1., 0.), t=(0., 1.),
                              points=[(k, (xs[k], y), None, None)
                                      for y in (k * b, (k + 1) * b)]))
        if k + 1 < n:
            top = min(tops[k], tops[k + 1])
            ends = [top] if gb_point else [(k + 1) * b, top]
            faces.append(dict(
                mu=mu, cohesion=m["c"] * (top - (k + 1) * b), tension=0.,
                n=(1., 0.), t=(0., 1.),
                points=[(k, (xs[k], y), k + 1, (xs[k + 1] + dx, y))
                        for y in ends]))
    return blocks, faces


def gb_limit(m):
    """Goodman and Bray's limit factor tan(phi) / tan(phi_limit) of column
    m (goodman_bray.analyse(): interblock forces at the top of the shorter
    block, no riser), or None where it needs tan(phi_limit) >= 1 (its
    sliding formula holds below 1; F_GB < tan(phi) then)."""
    g = dict(psi_p=m["psi_p"], dx=m["dx"], b=m["b"],
             heights=list(m["heights"]), unit_weight=UNIT_WEIGHT)
    lo, hi = 1e-6, 1. - 1e-9
    if goodman_bray.analyse(g, lo)[0] <= 0.:
        return math.inf
    if goodman_bray.analyse(g, hi)[0] > 0.:
        return None
    while hi - lo > 1e-12:
        mid = 0.5 * (lo + hi)
        if goodman_bray.analyse(g, mid)[0] > 0.:
            lo = mid
        else:
            hi = mid
    return math.tan(math.radians(m["phi"])) / (0.5 * (lo + hi))


def check_lp():
    """The LP on the project's column against goodman_bray.py (lines,
    passed): forces at the corners only -> Goodman and Bray's limit;
    anywhere on the faces -> goodman_bray.py --rigid's."""
    g = goodman_bray.COLUMN
    m = dict(psi_p=g["psi_p"], dx=g["dx"], b=g["b"], phi=45., c=0.,
             heights=goodman_bray.column_heights(g))
    t_gb = goodman_bray.limit_tan_phi(g)
    corner = lp_limit(*column_statics(m, risers=False, gb_point=True,
                                      gap=g["gap"]))
    anywhere = lp_limit(*column_statics(m, risers=False, gap=g["gap"]))
    with_risers = lp_limit(*column_statics(m, risers=True))
    gb_rigid = goodman_bray.rigid_limit(g, False)
    lines = [
        "LP check on the project's column (meshes/toppling_column.geo, "
        "tan(phi) = 1):",
        "  interblock forces at the top of the shorter block: F = %.6f, "
        "Goodman and Bray 1 / %.6f = %.6f (relative difference %.1e)"
        % (corner, t_gb, 1. / t_gb, abs(corner * t_gb - 1.)),
        "  interblock forces anywhere on the faces: F = %.6f, goodman_bray"
        ".py --rigid 1 / %.6f = %.6f (relative difference %.1e; mbfem's "
        "certificate 2.30110)" % (anywhere, gb_rigid, 1. / gb_rigid,
                                  abs(anywhere * gb_rigid - 1.)),
        "  the same blocks touching (no gaps) with the risers in contact: "
        "F = %.6f (%.2f %% above Goodman and Bray)"
        % (with_risers, 100. * (with_risers * t_gb - 1.))]
    passed = abs(corner * t_gb - 1.) < 1e-6 and \
        abs(anywhere * gb_rigid - 1.) < 1e-6
    if not passed:
        lines.append("  FAILED")
    return lines, passed


# ---------------------------------------------------------------------------
# Models
# ---------------------------------------------------------------------------

def snap_tops(m):
    """Moves each top closer than 0.3 element to a tread level or another
    top onto it (the mesh's rows would need slivers)."""
    b, h, n = m["b"], m["h"], len(m["heights"])
    levels = [k * b for k in range(n + 1)]
    for k in range(n):
        top = k * b + m["heights"][k]
        near = min(levels, key=lambda v: abs(v - top))
        if 0. < abs(near - top) < 0.3 * h and near - k * b > b:
            top = near
        m["heights"][k] = top - k * b
        levels.append(top)


def draw_one(rng, cohesive_share):
    p = rng.choice([1, 2])
    n = rng.randint(5, 14 if p == 2 else 20)
    dx = rng.uniform(0.5, 2.)
    psi_b = rng.uniform(10., 40.)
    psi_p = rng.uniform(max(0., psi_b - 25.), min(30., psi_b - 3.))
    b = dx * math.tan(math.radians(psi_b - psi_p))
    if rng.random() < 0.5:
        shape = "regular"
        crest = rng.randint(n // 3, max(n // 3, (2 * n) // 3 - 1))
        y0, yc, yn = (rng.uniform(1., 2.), rng.uniform(3., 6.),
                      rng.uniform(1., 2.5))
        heights = []
        for k in range(n):
            if k <= crest:
                y = y0 + (yc - y0) * k / max(crest, 1)
            else:
                y = yc + (yn - yc) * (k - crest) / (n - 1 - crest)
            heights.append(y * dx)
    else:
        shape = "random"
        heights = [rng.uniform(1., 6.) * dx for _ in range(n)]
    nx = rng.randint(2, 4) if p == 2 else rng.randint(3, 6)
    m = dict(n=n, p=p, dx=dx, psi_b=psi_b, psi_p=psi_p, b=b, shape=shape,
             heights=heights, phi=rng.uniform(20., 45.),
             c=(rng.uniform(0., 5e3) if rng.random() < cohesive_share
                else 0.),
             E=10. ** rng.uniform(9., 10.), nu=rng.uniform(0.2, 0.3),
             nx=nx, h=dx / nx, n_inc=rng.randint(1, 3))
    snap_tops(m)
    return m


def draw(rng, cohesive_share):
    """One model, drawn again until 0.25 < F_norise < 5 and 0.05 <
    tan(phi) / F_norise < 2 (the limits: docstring)."""
    while True:
        m = draw_one(rng, cohesive_share)
        try:
            F = lp_limit(*column_statics(m, risers=False))
            if not (0.25 < F < 5.):
                continue
            if not 0.05 < math.tan(math.radians(m["phi"])) / F < 2.:
                continue
            m["F_norise"] = F
            m["F"] = lp_limit(*column_statics(m))
        except RuntimeError:
            # HiGHS without a verdict at lp_limit()'s 1e-10 tolerances
            # (rare): drawn again rather than guessed.
            continue
        m["F_GB"] = gb_limit(m) if m["c"] == 0. else None
        return m


def model_text(i, m):
    return ("model %3d n=%2d p=%d %-7s dx=%.3f psi_b=%5.2f psi_p=%5.2f "
            "b=%.3f phi=%4.1f c=%4.0f E=%.2e nu=%.3f nx=%d inc=%d "
            "F=%.5f F_norise=%.5f F_GB=%s" % (
                i, m["n"], m["p"], m["shape"], m["dx"], m["psi_b"],
                m["psi_p"], m["b"], m["phi"], m["c"], m["E"], m["nu"],
                m["nx"], m["n_inc"], m["F"], m["F_norise"],
                "%.5f" % m["F_GB"] if m["F_GB"] else
                "<%.5f" % math.tan(math.radians(m["phi"]))))


# ---------------------------------------------------------------------------
# Mesh and parameter file
# ---------------------------------------------------------------------------

class Geo:
    """A gmsh .geo: points and lines shared by the rectangles that use
    them (so that the nodes of faces in contact coincide); vertical lines
    get level(top) - level(bottom) cells from one level map of y' for the
    whole column, so that both sides of every rectangle have as many
    nodes whatever their pieces (a structured surface needs that)."""

    def __init__(self, heights, h):
        self.h, self.points, self.lines, self.text = h, {}, {}, []
        self.surfaces = 0
        ys = sorted(set(round(y, 9) for y in heights))
        self.level, last = {}, None
        for y in ys:
            lv = int(round((y - ys[0]) / h))
            if last is not None:
                lv = max(lv, last + 1)
            self.level[y], last = lv, lv

    def cells_y(self, y0, y1):
        return self.level[round(y1, 9)] - self.level[round(y0, 9)]

    def point(self, x, y):
        key = (round(x, 9), round(y, 9))
        if key not in self.points:
            self.points[key] = len(self.points) + 1
            self.text.append("Point(%d) = {%.12g, %.12g, 0};"
                             % (self.points[key], x, y))
        return self.points[key]

    def line(self, a, b, cells):
        if (b, a) in self.lines:
            return -self.lines[(b, a)]
        if (a, b) not in self.lines:
            self.lines[(a, b)] = len(self.lines) + 1
            self.text.append("Line(%d) = {%d, %d}; Transfinite Curve{%d} = "
                             "%d;" % (self.lines[(a, b)], a, b,
                                      self.lines[(a, b)], cells + 1))
        return self.lines[(a, b)]

    def rectangle(self, x0, x1, y0, y1, cells_x, left=(), right=()):
        """A structured quadrilateral surface [x0, x1] x [y0, y1], its
        vertical sides split at the heights given; returns its id."""
        right = [y0] + sorted(v for v in right if y0 < v < y1) + [y1]
        left = [y0] + sorted(v for v in left if y0 < v < y1) + [y1]
        loop = [self.line(self.point(x0, y0), self.point(x1, y0), cells_x)]
        for lo, hi in zip(right[:-1], right[1:]):
            loop.append(self.line(self.point(x1, lo), self.point(x1, hi),
                                  self.cells_y(lo, hi)))
        loop.append(self.line(self.point(x1, y1), self.point(x0, y1),
                              cells_x))
        for lo, hi in reversed(list(zip(left[:-1], left[1:]))):
            loop.append(self.line(self.point(x0, hi), self.point(x0, lo),
                                  self.cells_y(lo, hi)))
        self.surfaces += 1
        s = self.surfaces
        corners = [self.point(x0, y0), self.point(x1, y0),
                   self.point(x1, y1), self.point(x0, y1)]
        self.text.append("Curve Loop(%d) = {%s}; Plane Surface(%d) = {%d};"
                         % (s, ", ".join(map(str, loop)), s, s))
        self.text.append("Transfinite Surface{%d} = {%s}; Recombine "
                         "Surface{%d};" % (s, ", ".join(map(str, corners)),
                                           s))
        return s


def geo_text(m, name):
    """The .geo of column m (frame of the treads, rotated by -psi_p):
    material ids 1 the base, k + 1 block k (1 the toe); boundary id 1 the
    base's bottom. The base reaches dx below the toe's tread and dx beyond
    the column at either end; it is built as a column of the base under
    each block, its upslope side rising to the next tread (the riser)."""
    dx, b, h = m["dx"], m["b"], m["h"]
    ys = m["heights"]
    n = len(ys)
    depth = margin = dx
    xs = [-k * dx for k in range(n)]
    tops = [k * b + ys[k] for k in range(n)]
    bottom = -depth
    geo = Geo([bottom] + [k * b for k in range(n)] + tops, h)
    nx = m["nx"]
    nm = max(1, int(round(margin / h)))
    base = []
    # The upslope margin (flat, at the top block's tread), the columns
    # under the blocks from the top down, the downslope margin.
    base.append(geo.rectangle(xs[-1] - margin, xs[-1], bottom,
                              (n - 1) * b, nm))
    for k in range(n - 1, -1, -1):
        right = ((k - 1) * b,) if k > 0 else ()
        base.append(geo.rectangle(xs[k], xs[k] + dx, bottom, k * b, nx,
                                  right=right))
    base.append(geo.rectangle(dx, dx + margin, bottom, 0., nm))
    blocks = []
    for k in range(n):
        left = right = ()
        if k + 1 < n:
            left = ((k + 1) * b, min(tops[k], tops[k + 1]))
        if k > 0:
            right = (min(tops[k], tops[k - 1]),)
        blocks.append(geo.rectangle(xs[k], xs[k] + dx, k * b, tops[k], nx,
                                    left, right))
    bottoms = [abs(geo.line(geo.point(x0, bottom), geo.point(x1, bottom),
                            0)) for x0, x1 in
               [(xs[-1] - margin, xs[-1])]
               + [(xs[k], xs[k] + dx) for k in range(n - 1, -1, -1)]
               + [(dx, dx + margin)]]
    every = ", ".join(map(str, base + blocks))
    out = ["// scripts/random_toppling_columns.py: %s" % name,
           "// %d blocks, dx = %.6g m, b = %.6g m, psi_p = %.6g deg, "
           "heights (toe first) %s" % (n, dx, b, m["psi_p"], ", ".join(
               "%.6g" % y for y in ys))] + geo.text
    out.append("Rotate {{0, 0, 1}, {0, 0, 0}, -%.12g * Pi / 180} "
               "{ Surface{%s}; }" % (m["psi_p"], every))
    out.append("Physical Surface(1) = {%s};" % ", ".join(map(str, base)))
    for k, s in enumerate(blocks):
        out.append("Physical Surface(%d) = {%d};" % (k + 2, s))
    out.append("Physical Curve(1) = {%s};" % ", ".join(map(str, bottoms)))
    return "\n".join(out) + "\n"


def write_mesh(folder, i, m):
    name = "column%03d" % i
    geo = os.path.join(folder, name + ".geo")
    mesh = geo[:-4] + ".msh"
    if not os.path.exists(mesh):
        with open(geo, "w") as f:
            f.write(geo_text(m, name + ".geo"))
        subprocess.run(["gmsh", "-2", "-format", "msh22", geo, "-o", mesh],
                       check=True, stdout=subprocess.DEVNULL)
    return geo, mesh


def reference(m, lam):
    """The limit a run at lam is a multiple of: below the limit the LP
    without the risers (F_norise <= mbfem's pairs' limit), above it the
    LP with them (F >= mbfem's pairs' limit); see the docstring."""
    return m["F_norise"] if lam < 1. else m["F"]


def write_case(folder, name, mesh, m, i, seed, lam):
    factor = lam * reference(m, lam)
    mu = math.tan(math.radians(m["phi"])) / factor
    c = m["c"] / factor
    prm = os.path.join(folder, name + ".prm")
    with open(prm, "w") as f:
        f.write("""# Random toppling column (scripts/random_toppling_columns.py --seed %d
# --models %d), %.2f of its rigid-block limit %.9g (tan(phi) = %.9g
# divided by %.9g on every joint).
# %s
# heights from the toe up (m): %s
set Dimension = 2
subsection Mesh
  set Source    = gmsh
  set Mesh file = %s
end
subsection Finite element
  set Polynomial degree = %d
end
subsection Material
  set Young's modulus = %.6g
  set Poisson's ratio = %.6g
  set Unit weight     = %g
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 1: xy
  set Gravity ramp time = 0
end
subsection Load history
  set Number of increments = %d
end
subsection Contact
  set Interfaces           = all
  set Friction coefficient = %.9g
  set Cohesion             = %.9g
end
subsection Output
  set Base name = column
  set Directory = %s
  set Write VTU = false
end
""" % (seed, i, lam, reference(m, lam), math.tan(math.radians(m["phi"])), factor,
            model_text(i, m), ", ".join("%.6g" % y for y in m["heights"]),
            os.path.basename(mesh), m["p"], m["E"], m["nu"], UNIT_WEIGHT,
            m["n_inc"], mu, c, name))
    return prm


# ---------------------------------------------------------------------------
# Runs
# ---------------------------------------------------------------------------

class Run:
    """One mbfem run: outcome, exit code, seconds, the certificate's
    strength factor (or None) and the failing increment's message line."""

    def __init__(self, mbfem, folder, name, prm, timeout):
        env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
        here = os.path.dirname(os.path.abspath(mbfem))
        if os.path.exists(os.path.join(here, "libmbfem-lib.so")):
            env["LD_LIBRARY_PATH"] = here + (
                ":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH")
                else "")
        shutil.rmtree(os.path.join(folder, name), ignore_errors=True)
        start = time.time()
        try:
            r = subprocess.run([mbfem, prm], cwd=folder, capture_output=True,
                               text=True, timeout=timeout, env=env)
            self.code, out, err = r.returncode, r.stdout, r.stderr
            self.outcome = OUTCOME.get(r.returncode, "error")
        except subprocess.TimeoutExpired as e:
            self.code, self.outcome = None, "timeout"
            out = e.stdout.decode() if isinstance(e.stdout, bytes) \
                else (e.stdout or "")
            err = e.stderr.decode() if isinstance(e.stderr, bytes) \
                else (e.stderr or "")
        self.seconds = time.time() - start
        for suffix, text in ((".out", out), (".err", err)):
            with open(os.path.join(folder, name + suffix), "w") as f:
                f.write(text)
        s = re.search(r"strength factor ([0-9.e+-]+)|divided by up to "
                      r"([0-9.e+-]+) \(strength factor\)", err)
        self.certificate = float(s.group(1) or s.group(2)) if s else None
        # The failing increment's line of each method, shortened.
        methods, first = [], ""
        for line in err.splitlines():
            line = line.strip()
            if line and not first and line != "mbfem: error":
                first = line
            if line.startswith("Load increment"):
                methods.append(line if not methods else
                               line.split(": ", 1)[-1][:110])
        self.message = " | ".join(methods) if methods else first[:300]
        self.increments = len(re.findall(r"^\s*Load increment \d+",
                                         out, re.M))
        self.prm = prm

    def describe(self, factor):
        text = "%s%s" % (self.outcome, "" if self.code in (None, 0, 2, 3, 4)
                         else " (exit %s)" % self.code)
        if self.certificate:
            text += " cert LP F %.5f" % (factor * self.certificate)
        return text + " %.1f s" % self.seconds


def wrong(lam, run):
    """Whether the run's answer is not the right one (0 below the limit,
    2 above it)."""
    return run.outcome != ("converged" if lam < 1. else "certified-none")


def keep_failure(keep, geo, mesh, run):
    """Copies the run's inputs (.geo, .msh, .prm), its screen output and
    the contact problem its failed increment wrote (its folder's
    *-failed-problem-*, for scripts/check_contact_problem_2d.py)."""
    os.makedirs(keep, exist_ok=True)
    for path in (geo, mesh, run.prm, run.prm[:-4] + ".out",
                 run.prm[:-4] + ".err"):
        if os.path.exists(path) and not os.path.exists(
                os.path.join(keep, os.path.basename(path))):
            shutil.copy(path, keep)
    results = run.prm[:-4]
    problems = [f for f in (os.listdir(results) if os.path.isdir(results)
                            else []) if "-failed-problem-" in f]
    if problems:
        target = os.path.join(keep, os.path.basename(results))
        os.makedirs(target, exist_ok=True)
        for f in problems:
            shutil.copy(os.path.join(results, f), target)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--count", type=int, default=40)
    parser.add_argument("--seed", type=int, default=None,
                        help="the draw's seed (default: a fresh one, "
                        "printed first)")
    parser.add_argument("--models", default="",
                        help="run only these models (comma-separated "
                        "indices; the others are drawn, not run)")
    parser.add_argument("--mbfem", default=os.path.join(SOURCE, "build",
                                                        "mbfem"))
    parser.add_argument("--work", default="",
                        help="folder for the runs (default: a fresh "
                        "temporary one)")
    parser.add_argument("--keep", default="",
                        help="copy the .geo, .msh, .prm, .out, .err of "
                        "every failure into this folder")
    parser.add_argument("--timeout", type=float, default=300.,
                        help="seconds per mbfem run (a timeout is its own "
                        "verdict)")
    parser.add_argument("--cohesive-share", type=float, default=0.,
                        help="share of the models with c up to 5 kPa "
                        "(default 0: c = 0 everywhere)")
    parser.add_argument("--budget", type=float, default=0.,
                        help="start no new model after this many seconds "
                        "of runs (0: no limit); the summary says how many "
                        "were run")
    parser.add_argument("--flat", action="store_true",
                        help="a diagnostic: the models drawn as usual, "
                        "then run with the steps removed (b = 0, psi_b = "
                        "psi_p: every block on one plane, no risers; F = "
                        "F_norise recomputed)")
    parser.add_argument("--dry-run", action="store_true",
                        help="draw and mesh the models, run nothing")
    args = parser.parse_args()
    if args.seed is None:
        args.seed = int.from_bytes(os.urandom(4), "little") % 1000000
    print("seed %d (--seed %d repeats this draw)" % (args.seed, args.seed),
          flush=True)
    if not args.dry_run and not os.access(args.mbfem, os.X_OK):
        sys.exit("--mbfem: %s is not an executable" % args.mbfem)
    lines, passed = check_lp()
    print("\n".join(lines), flush=True)
    if not passed:
        sys.exit("the LP does not reproduce goodman_bray.py; no runs")
    work = args.work or tempfile.mkdtemp(prefix="mbfem-toppling-")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(args.seed)
    models = [draw(rng, args.cohesive_share) for _ in range(args.count)]
    chosen = [int(v) for v in args.models.split(",") if v]
    counts, failures, runs = {}, [], []
    start = time.time()
    n_models = 0
    for i, m in enumerate(models):
        if chosen and i not in chosen:
            continue
        if args.budget and time.time() - start > args.budget:
            print("budget of %.0f s spent: models %d to %d not run"
                  % (args.budget, i, len(models) - 1), flush=True)
            break
        if args.flat:
            m["b"], m["psi_b"] = 0., m["psi_p"]
            try:
                m["F_norise"] = m["F"] = lp_limit(*column_statics(m))
            except RuntimeError:
                print("model %3d: no verdict of HiGHS on the flat column; "
                      "not run" % i, flush=True)
                continue
            m["F_GB"] = gb_limit(m) if m["c"] == 0. else None
        n_models += 1
        geo, mesh = write_mesh(work, i, m)
        print(model_text(i, m), flush=True)
        if args.dry_run:
            continue
        for lam in LAMBDAS:
            name = "column%03d-%.2f" % (i, lam)
            prm = write_case(work, name, mesh, m, i, args.seed, lam)
            run = Run(args.mbfem, work, name, prm, args.timeout)
            c = counts.setdefault(lam, {})
            c[run.outcome] = c.get(run.outcome, 0) + 1
            bad = wrong(lam, run)
            runs.append((i, lam, run))
            print("  model %3d n=%2d p=%d at %.2f: %s%s" % (
                i, m["n"], m["p"], lam,
                run.describe(lam * reference(m, lam)),
                "  <-- FAILURE" if bad else ""), flush=True)
            if bad:
                failures.append((i, lam, run))
                if args.keep:
                    keep_failure(args.keep, geo, mesh, run)
    seconds = time.time() - start
    if args.dry_run:
        return 0
    print("\nfailures (%d): exit code 3 below the limit, converged above "
          "it, timeouts, errors, anything not 0 below or 2 above" %
          len(failures))
    for i, lam, run in failures:
        m = models[i]
        print("  model %3d (n=%d, p=%d, %s, inc=%d) at %.2f: %s; %s" % (
            i, m["n"], m["p"], m["shape"], m["n_inc"], lam, run.outcome,
            run.message or "(no message)"))
    print("\nsummary (seed %d, %d models, %.0f s): runs per multiple of the "
          "limit" % (args.seed, n_models, seconds))
    print("  %-6s %s" % ("lambda", " ".join("%14s" % c for c in COLUMNS)))
    for lam in LAMBDAS:
        c = counts.get(lam, {})
        print("  %-6.2f %s" % (lam, " ".join("%14d" % c.get(k, 0)
                                             for k in COLUMNS)))
    for helps, what in ((False, "F = F_norise (the risers do not help)"),
                        (True, "F > F_norise (the risers help)")):
        ids = [i for i in {r[0] for r in runs}
               if (models[i]["F"] > models[i]["F_norise"] * (1. + 1e-6))
               == helps]
        print("  models with %s: %d; exit code 3 below the limit in %d "
              "of them" % (what, len(ids), len({
                  i for i, lam, run in runs if i in ids and lam < 1.
                  and run.outcome == "not-converged"})))
    certs = [(run.certificate * lam * reference(models[i], lam), i)
             for i, lam, run in runs if run.certificate]
    if certs:
        low = min((c / models[i]["F_norise"], i) for c, i in certs)
        high = max((c / models[i]["F"], i) for c, i in certs)
        print("  mbfem's certificate's limit against F_norise and F (%d "
              "runs with a certificate): smallest limit / F_norise %.6f "
              "(model %d), largest limit / F %.6f (model %d)"
              % ((len(certs),) + low + high))
    print("work folder:", work)
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
