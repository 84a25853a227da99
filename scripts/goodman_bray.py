#!/usr/bin/env python3
"""Goodman and Bray's limit-equilibrium analysis of block toppling.

A column of rectangular blocks of width dx on a stepped base: each block
stands on its own step (tread), the treads dip at psi_p, the blocks' sides
are normal to the treads, and all faces (treads and the faces between
blocks) have the friction angle phi. Blocks are numbered from the toe
(1) upwards (n). Starting from the top block (no force from above), the
force P_{n-1} that block n - 1 must exert on block n to hold it is

  toppling  P_{n-1,t} = [P_n (M_n - dx tan phi)
                         + (W_n / 2) (y_n sin psi_p - dx cos psi_p)] / L_n
  sliding   P_{n-1,s} = P_n - W_n (tan phi cos psi_p - sin psi_p)
                                / (1 - tan^2 phi)

and P_{n-1} = max(P_{n-1,t}, P_{n-1,s}): the block topples if the first is
the larger, slides if the second; if both are <= 0 it is stable on its
own (P_{n-1} = 0). W_n is the block's weight, y_n its height, M_n and L_n
the heights above its tread at which P_n and P_{n-1} act: the top of the
shorter of the two faces in contact (the corner on which the taller block
rotates), so M_n = y_n and L_n = y_n - a1 below the crest of the slope,
M_n = y_n - a2 and L_n = y_n above it, as the method assumes. The shear
force on each face in contact is Q = P tan phi (full friction mobilised on
every face). The base reactions are R_n = W_n cos psi_p + (P_n - P_{n-1})
tan phi and S_n = W_n sin psi_p + P_n - P_{n-1}. The force needed at the
toe to hold the column is P_0; the limit friction is the tan phi at which
P_0 = 0, found here by bisection on tan phi (to 1e-12).

Sources: Goodman, R. E. and Bray, J. W. (1976), "Toppling of rock
slopes", Proc. Specialty Conf. on Rock Engineering for Foundations and
Slopes, ASCE, Boulder, vol. 2, 201-234; Hoek and Bray, "Rock Slope
Engineering" (3rd ed. 1981), ch. 10; Wyllie and Mah, "Rock Slope
Engineering" (4th ed. 2004), ch. 9, section 9.4 (eqs. 9.16 to 9.24: M_n,
L_n below / at / above the crest, P_{n-1,t}, P_{n-1,s}, R_n, S_n). The
structure (stable blocks at the top, a toppling set, a sliding set at the
toe pushed by it) and the points of application M_n, L_n were checked
against the lecture notes of IIT (BHU), "Limit equilibrium analysis for
toppling failure" (www.iitbhu.ac.in/faculty/min/rajesh-rai/NMEICT-Slope/
lecture/c3/l11.html) and Wyllie and Mah ch. 9 as reproduced at
what-when-how.com (Rock-Slope-Engineering-Civil-and-Mining-239); the
formulas above also follow from the equilibrium of one block (moments
about its toe for toppling, forces along and normal to its tread with
S = R tan phi for sliding), which is how they are coded below.

The geometry is given here once (COLUMN, and PAIR for the two-block case
of parameters/toppling_pair.prm); `--write-geo` writes
meshes/toppling_column.geo from COLUMN, so the mesh and this analysis
read the same numbers.

  python3 scripts/goodman_bray.py              # the column: limit, table
  python3 scripts/goodman_bray.py --pair       # the two-block pair
  python3 scripts/goodman_bray.py --tan-phi 0.5   # the table at mu = 0.5
  /usr/bin/python3 scripts/goodman_bray.py --rigid  # and the statics LPs

--rigid also bisects on mu for the smallest friction at which the blocks,
taken rigid, admit contact forces at all (a linear program for each mu:
equilibrium of every block, Coulomb's cone at each contact point), once
with the interblock forces allowed anywhere on the faces in contact (what
mbfem's statics certificate does) and once only at the top of the
shorter block (Goodman and Bray's point). The latter gives Goodman and
Bray's limit, the former mbfem's certificate's.
  python3 scripts/goodman_bray.py --write-geo meshes/toppling_column.geo
"""

import argparse
import math
import sys

# The column (meshes/toppling_column.geo, parameters/toppling_column.prm).
# Heights in the frame of the treads: below the crest y_n = n (a1 - b),
# above it y_n = y_{n-1} - a2 - b (Goodman and Bray's regular slope: the
# face rises a1 and the top falls a2 per block, each tread b above the one
# downslope). Every length is a multiple of the element size h.
COLUMN = dict(psi_p=20., dx=1.0, a1=1.0, a2=0.75, b=0.25, crest=5, n=8,
              gap=1e-4, h=0.25, depth=1.0, margin=0.5, unit_weight=25e3)

# The two-block pair of parameters/toppling_pair.prm: a toe block 2 x 2 m
# and a column 2 x 8 m on one flat base (no step) dipping 20 degrees.
PAIR = dict(psi_p=20., dx=2.0, heights=[2.0, 8.0], b=0., unit_weight=25e3)


def column_heights(g):
    """The heights y_1 (toe) ... y_n of Goodman and Bray's regular slope."""
    heights = []
    for k in range(1, g["n"] + 1):
        if k <= g["crest"]:
            heights.append(k * (g["a1"] - g["b"]))
        else:
            heights.append(heights[-1] - g["a2"] - g["b"])
    if min(heights) <= 0.:
        sys.exit("COLUMN: a block of height <= 0 (heights %s)" % heights)
    return heights


def blocks_of(g):
    """[(tread elevation, height)] from the toe up, in the treads' frame."""
    heights = g["heights"] if "heights" in g else column_heights(g)
    return [(k * g["b"], y) for k, y in enumerate(heights)]


def contact_heights(blocks, k):
    """(M, L) of block k (0-based): the heights above its tread of the
    forces from the block above and the block below, each at the top of
    the shorter of the two faces in contact."""
    base, y = blocks[k]
    top = base + y
    if k + 1 < len(blocks):
        M = min(top, sum(blocks[k + 1])) - base
    else:
        M = 0.
    L = min(top, sum(blocks[k - 1])) - base if k > 0 else y
    return M, L


def analyse(g, tan_phi):
    """Goodman and Bray from the top block down at tan phi: the force at
    the toe P_0 and one row per block (from the toe up): number, height,
    weight, M, L, P_n (from above), P_{n-1,t}, P_{n-1,s}, mode, R, S."""
    blocks = blocks_of(g)
    psi = math.radians(g["psi_p"])
    s, c, dx, t = math.sin(psi), math.cos(psi), g["dx"], tan_phi
    P, rows = 0., []
    for k in range(len(blocks) - 1, -1, -1):
        y = blocks[k][1]
        W = g["unit_weight"] * dx * y
        M, L = contact_heights(blocks, k)
        topple = (P * (M - dx * t) + 0.5 * W * (y * s - dx * c)) / L
        slide = P - W * (t * c - s) / (1. - t * t)
        below = max(topple, slide)
        # Stable on its own: neither mode needs a force from below
        # (relative to the weight, so that the toe at the limit, where
        # P_0 = 0 to round-off, is named by its mode).
        if below < -1e-9 * W:
            mode, below = "stable", 0.
        else:
            mode = "topples" if topple >= slide else "slides"
        R = W * c + (P - below) * t
        S = W * s + P - below
        rows.append((k + 1, y, W, M, L, P, topple, slide, mode, R, S))
        P = below
    return P, rows[::-1]


def limit_tan_phi(g):
    """tan phi at which the force needed at the toe is zero (bisection
    on tan phi in (0, 1) to 1e-12; the sliding formula holds for
    tan phi < 1)."""
    lo, hi = 1e-6, 1. - 1e-9
    if analyse(g, lo)[0] <= 0. or analyse(g, hi)[0] > 0.:
        sys.exit("no limit friction with tan(phi) in (0, 1)")
    while hi - lo > 1e-12:
        mid = 0.5 * (lo + hi)
        if analyse(g, mid)[0] > 0.:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def report(g, name, tan_phi=None):
    """Prints the limit and the table of the blocks at the limit (or at
    tan_phi if given)."""
    t = limit_tan_phi(g)
    print("%s: psi_p = %g deg, dx = %g m, %d blocks, unit weight %g N/m^3"
          % (name, g["psi_p"], g["dx"], len(blocks_of(g)),
             g["unit_weight"]))
    print("limit: tan(phi) = %.6f, phi = %.4f deg, F = 1/tan(phi) = %.6f"
          % (t, math.degrees(math.atan(t)), 1. / t))
    if tan_phi is not None:
        toe, rows = analyse(g, tan_phi)
        print("at tan(phi) = %.6f (F = %.6f, %.4f of the limit's): force "
              "needed at the toe P_0 = %.1f" % (tan_phi, 1. / tan_phi,
                                                t / tan_phi, toe))
    else:
        rows = analyse(g, t)[1]
    print("%5s %6s %9s %6s %6s %10s %10s %10s %8s %10s %10s" % (
        "block", "y", "W", "M", "L", "P_n", "P_n-1,t", "P_n-1,s", "mode",
        "R", "S"))
    for row in rows[::-1]:
        print("%5d %6.3f %9.1f %6.3f %6.3f %10.1f %10.1f %10.1f %8s "
              "%10.1f %10.1f" % row)
    return t


def rigid_contacts(g, corners_only):
    """The contact points of the rigid-block statics: both ends of each
    tread, and of each face in contact either both ends (a force anywhere
    on the face is a combination of forces at its ends) or only the top of
    the shorter block (Goodman and Bray's point). Each entry: (block on
    side a or None for the base, block on side b, point, normal on b), in
    the frame of the treads, the toe block on 0 <= x' <= dx."""
    blocks, dx = blocks_of(g), g["dx"]
    xs = [-k * dx for k in range(len(blocks))]
    out = []
    for k, (base, y) in enumerate(blocks):
        out += [(None, k, (x, base), (0., 1.)) for x in (xs[k], xs[k] + dx)]
    for k in range(len(blocks) - 1):
        top = min(sum(blocks[k]), sum(blocks[k + 1]))
        ends = [top] if corners_only else [blocks[k + 1][0], top]
        out += [(k + 1, k, (xs[k], y), (1., 0.)) for y in ends]
    return blocks, xs, out


def rigid_admissible(g, mu, corners_only):
    """Whether contact forces with |T| <= mu N at the points of
    rigid_contacts hold every block against its weight (a linear
    program, scipy's HiGHS)."""
    import numpy as np
    from scipy.optimize import linprog
    blocks, xs, contacts = rigid_contacts(g, corners_only)
    psi, dx, m = math.radians(g["psi_p"]), g["dx"], len(contacts)
    A, rhs = np.zeros((3 * len(blocks), 2 * m)), np.zeros(3 * len(blocks))
    for k, (base, y) in enumerate(blocks):
        W = g["unit_weight"] * dx * y
        cx, cy = xs[k] + 0.5 * dx, base + 0.5 * y
        wx, wy = W * math.sin(psi), -W * math.cos(psi)
        rhs[3 * k:3 * k + 3] = [-wx, -wy, -(cx * wy - cy * wx)]
    for i, (a, b, (px, py), (nx, ny)) in enumerate(contacts):
        for block, sign in ((b, 1.), (a, -1.)):
            if block is None:
                continue
            for j, (dx_, dy_) in ((2 * i, (nx, ny)), (2 * i + 1, (-ny, nx))):
                fx, fy = sign * dx_, sign * dy_
                A[3 * block:3 * block + 3, j] += [fx, fy, px * fy - py * fx]
    cone = np.zeros((2 * m, 2 * m))
    for i in range(m):
        cone[2 * i, 2 * i:2 * i + 2] = [-mu, 1.]
        cone[2 * i + 1, 2 * i:2 * i + 2] = [-mu, -1.]
    bounds = [(0., None), (None, None)] * m
    result = linprog(np.zeros(2 * m), A_ub=cone, b_ub=np.zeros(2 * m),
                     A_eq=A, b_eq=rhs, bounds=bounds, method="highs")
    return result.status == 0


def rigid_limit(g, corners_only):
    """The smallest mu with admissible forces (bisection to 1e-9)."""
    lo, hi = 1e-3, 5.
    while hi - lo > 1e-9:
        mid = 0.5 * (lo + hi)
        if rigid_admissible(g, mid, corners_only):
            hi = mid
        else:
            lo = mid
    return hi


class Geo:
    """A gmsh .geo under construction: points and lines shared by the
    rectangles that use them, each line meshed with elements of size h."""

    def __init__(self, h):
        self.h, self.points, self.lines, self.text = h, {}, {}, []
        self.surfaces = 0

    def point(self, x, y):
        key = (round(x, 9), round(y, 9))
        if key not in self.points:
            self.points[key] = len(self.points) + 1
            self.text.append("Point(%d) = {%.9g, %.9g, 0};"
                             % (self.points[key], x, y))
        return self.points[key]

    def line(self, a, b):
        """The signed id of the line from point a to point b."""
        if (b, a) in self.lines:
            return -self.lines[(b, a)]
        if (a, b) not in self.lines:
            self.lines[(a, b)] = len(self.lines) + 1
            coords = {v: k for k, v in self.points.items()}
            length = math.dist(coords[a], coords[b])
            cells = max(1, round(length / self.h))
            if length > 0.5 * self.h and abs(cells * self.h - length) > 1e-9:
                sys.exit("COLUMN: a length %g m is not a multiple of h = %g"
                         % (length, self.h))
            self.text.append("Line(%d) = {%d, %d}; Transfinite Curve{%d} = "
                             "%d;" % (self.lines[(a, b)], a, b,
                                      self.lines[(a, b)], cells + 1))
        return self.lines[(a, b)]

    def rectangle(self, x0, x1, y0, y1, left=(), right=()):
        """A structured quadrilateral surface [x0, x1] x [y0, y1], its
        vertical sides split at the heights given; returns its id and
        {(side, lower height): line id} of its vertical pieces."""
        right = [y0] + sorted(v for v in right if y0 < v < y1) + [y1]
        left = [y0] + sorted(v for v in left if y0 < v < y1) + [y1]
        pieces, loop = {}, [self.line(self.point(x0, y0),
                                      self.point(x1, y0))]
        for lo, hi in zip(right[:-1], right[1:]):
            loop.append(self.line(self.point(x1, lo), self.point(x1, hi)))
            pieces[("right", lo)] = abs(loop[-1])
        loop.append(self.line(self.point(x1, y1), self.point(x0, y1)))
        for lo, hi in reversed(list(zip(left[:-1], left[1:]))):
            loop.append(self.line(self.point(x0, hi), self.point(x0, lo)))
            pieces[("left", lo)] = abs(loop[-1])
        self.surfaces += 1
        s = self.surfaces
        corners = [self.point(x0, y0), self.point(x1, y0),
                   self.point(x1, y1), self.point(x0, y1)]
        self.text.append("Curve Loop(%d) = {%s}; Plane Surface(%d) = {%d};"
                         % (s, ", ".join(map(str, loop)), s, s))
        self.text.append("Transfinite Surface{%d} = {%s}; Recombine "
                         "Surface{%d};" % (s, ", ".join(map(str, corners)),
                                           s))
        return s, pieces


def base_surfaces(geo, g, blocks, xs):
    """The fixed base: a column under each block (its top the block's
    tread), one under each gap (its top the lower tread, so that the
    riser faces the lower block across the gap without touching it) and
    a margin at each end; returns its surfaces and its bottom lines."""
    dx, depth, m = g["dx"], g["depth"], g["margin"]
    n, bottom = len(blocks), -depth
    columns = [(xs[-1] - m, xs[-1], blocks[-1][0], ())]
    for k in range(n - 1, -1, -1):
        riser = (blocks[k - 1][0],) if k > 0 else ()
        columns.append((xs[k], xs[k] + dx, blocks[k][0], riser))
        if k > 0:
            columns.append((xs[k] + dx, xs[k - 1], blocks[k - 1][0], ()))
    columns.append((dx, dx + m, blocks[0][0], ()))
    surfaces = []
    for x0, x1, top, right in columns:
        surfaces.append(geo.rectangle(x0, x1, bottom, top, right=right)[0])
    lines = [abs(geo.line(geo.point(x0, bottom), geo.point(x1, bottom)))
             for x0, x1, _, _ in columns]
    return surfaces, lines


def block_surfaces(geo, g, blocks, xs):
    """Block k on its tread, its sides split where the faces in contact
    with its neighbours end; returns its surfaces (one each) and the
    boundary ids: {id: line}, 10 + 2j on the upper block's face and
    11 + 2j on the lower block's face of contact j (blocks j + 1, j)."""
    surfaces, ids, n = [], {}, len(blocks)
    for k, (base, y) in enumerate(blocks):
        top = base + y
        left = right = ()
        if k + 1 < n:
            upper = min(top, sum(blocks[k + 1]))
            left = (blocks[k + 1][0], upper)
        if k > 0:
            right = (min(top, sum(blocks[k - 1])),)
        s, pieces = geo.rectangle(xs[k], xs[k] + g["dx"], base, top, left,
                                  right)
        surfaces.append(s)
        if k + 1 < n:
            ids[11 + 2 * (k + 1)] = pieces[("left", blocks[k + 1][0])]
        if k > 0:
            ids[10 + 2 * k] = pieces[("right", base)]
    return surfaces, ids


def geo(g, blocks):
    """The .geo of the column: built in the frame of the treads (x' down
    the dip, y' normal to the treads), then rotated by -psi_p."""
    geo = Geo(g["h"])
    xs = [-k * (g["dx"] + g["gap"]) for k in range(len(blocks))]
    base, bottom = base_surfaces(geo, g, blocks, xs)
    surfaces, ids = block_surfaces(geo, g, blocks, xs)
    every = ", ".join(map(str, base + surfaces))
    out = [HEADER % dict(g, n=len(blocks), heights=", ".join(
        "%g" % y for _, y in blocks))] + geo.text
    out.append("Rotate {{0, 0, 1}, {0, 0, 0}, -%.9g * Pi / 180} "
               "{ Surface{%s}; }" % (g["psi_p"], every))
    out.append("Physical Surface(1) = {%s};" % ", ".join(map(str, base)))
    for k, s in enumerate(surfaces):
        out.append("Physical Surface(%d) = {%d};" % (k + 2, s))
    out.append("Physical Curve(1) = {%s};" % ", ".join(map(str, bottom)))
    for i in sorted(ids):
        out.append("Physical Curve(%d) = {%d};" % (i, ids[i]))
    return "\n".join(out) + "\n"


HEADER = """\
// Goodman and Bray's toppling of a block column on a stepped base (issue
// 13). WRITTEN BY scripts/goodman_bray.py --write-geo FROM ITS COLUMN
// CONSTANTS: change those, not this file. %(n)d blocks of width dx = %(dx)g m,
// heights from the toe up (m):
//   %(heights)s
// (the face rises a1 = %(a1)g m and the top falls a2 = %(a2)g m per block,
// the crest at block %(crest)d), each on its own tread b = %(b)g m above the
// one downslope, %(gap)g m apart; treads dipping psi_p = %(psi_p)g deg.
// Built in the frame of the treads (x' down the dip, y' normal to them),
// the toe block on 0 <= x' <= dx, then rotated by -psi_p. Structured quadrilaterals of
// h = %(h)g m. The fixed base reaches %(depth)g m below the toe's tread.
// Material ids: 1 the base, k + 1 block k (1 the toe block). Boundary ids:
// 1 the base's bottom; for the contact j between blocks j + 1 and j, the
// faces in contact (from the upper block's tread to the top of the
// shorter block): 10 + 2j on block j + 1, 11 + 2j on block j.
//
// Regenerate (gmsh 4.8.4, Debian 12):
//   python3 scripts/goodman_bray.py --write-geo meshes/toppling_column.geo
//   gmsh -2 -format msh22 meshes/toppling_column.geo -o meshes/toppling_column.msh
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--pair", action="store_true",
                        help="the two-block pair of toppling_pair.prm")
    parser.add_argument("--tan-phi", type=float, help="the table at this "
                        "tan(phi) instead of at the limit")
    parser.add_argument("--rigid", action="store_true", help="also the "
                        "rigid-block statics limits (needs scipy)")
    parser.add_argument("--write-geo", metavar="FILE",
                        help="write the column's gmsh .geo to FILE")
    args = parser.parse_args()
    if args.write_geo:
        with open(args.write_geo, "w") as f:
            f.write(geo(COLUMN, blocks_of(COLUMN)))
        return 0
    g = PAIR if args.pair else COLUMN
    report(g, "toppling pair (parameters/toppling_pair.prm)" if args.pair
           else "toppling column (parameters/toppling_column.prm)",
           args.tan_phi)
    if args.rigid:
        try:
            import scipy  # noqa: F401
        except ImportError:
            sys.exit("--rigid needs scipy (e.g. /usr/bin/python3 here)")
        for corners, what in ((False, "anywhere on the faces in contact"),
                              (True, "at the top of the shorter block")):
            mu = rigid_limit(g, corners)
            print("rigid-block statics, interblock forces %s: mu = %.6f, "
                  "F = %.6f" % (what, mu, 1. / mu))
    return 0


if __name__ == "__main__":
    sys.exit(main())
