#!/usr/bin/env python3
"""The 3D wedge of parameters/wedge_3d.prm: Hoek and Bray's factor of
safety against the rigid-block statics limit, computed independently of
mbfem.

The wedge rests on two planes (dip / dip direction 40/135 and 40/225),
c = 0, phi = 35 deg. Hoek and Bray take the shear on both planes parallel
to their line of intersection, the direction in which the wedge slides;
the normal forces then balance the weight's component across that line,
and F = tan(phi) (N1 + N2) / (W along the line) = 1.3249.

Statics alone (the linear program of mbfem's certificate) lets each
plane's shear point anywhere within its Coulomb cone. Shear across the
line of intersection can wedge the block between the planes: it raises
both normal forces, and with them the friction available along the line.
This script finds the largest F for which forces N_i >= 0, |T_i| <=
tan(phi) N_i / F on the two planes balance the weight, by bisection on F,
each step a linear program (scipy's HiGHS) with each cone replaced by a
polygon of --facets sides, circumscribed (its limit is an upper bound of
the cone's) and inscribed (a lower bound). Moments are left out: with the
forces spread over the planes they can always be balanced, and leaving
them out can only raise the limit.

  /usr/bin/python3 scripts/wedge_statics.py [--facets 720]

mbfem's certificate (moments included, a circumscribed polygon of 64
sides) gives 1.37365 (doc/state_iteration.md); dividing by its faceting
factor 1/cos(pi/64) = 1.0012 gives a lower bound 1.3720 of the cone's
limit with moments; this script's circumscribed value is an upper bound
without them. Between Hoek and Bray's 1.3249 and this limit statically
admissible forces exist, so no statics certificate of "no equilibrium"
can exist there.
"""

import argparse
import math

import numpy as np
from scipy.optimize import linprog

PLANES = [(40., 135.), (40., 225.)]  # dip, dip direction (deg)
TAN_PHI = math.tan(math.radians(35.))


def normal(dip, dip_direction):
    """Upward unit normal; x east, y north, z up, azimuth from north."""
    d, a = math.radians(dip), math.radians(dip_direction)
    return np.array([math.sin(d) * math.sin(a), math.sin(d) * math.cos(a),
                     math.cos(d)])


def tangents(n):
    t1 = np.cross(n, [0., 0., 1.])
    t1 /= np.linalg.norm(t1)
    return t1, np.cross(n, t1)


def admissible(factor, facets, kappa):
    """Forces (N, T1, T2) on each plane balancing a unit weight, with the
    shear inside the polygon t . e_j <= kappa mu N of facets sides."""
    mu = TAN_PHI / factor
    a_eq = np.zeros((3, 6))
    a_ub = []
    for i, plane in enumerate(PLANES):
        n = normal(*plane)
        t1, t2 = tangents(n)
        a_eq[:, 3 * i:3 * i + 3] = np.array([n, t1, t2]).T
        for j in range(facets):
            angle = 2. * math.pi * j / facets
            row = np.zeros(6)
            row[3 * i:3 * i + 3] = (-kappa * mu, math.cos(angle),
                                    math.sin(angle))
            a_ub.append(row)
    result = linprog(np.zeros(6), A_ub=np.array(a_ub),
                     b_ub=np.zeros(len(a_ub)), A_eq=a_eq,
                     b_eq=np.array([0., 0., 1.]),
                     bounds=[(0, None), (None, None), (None, None)] * 2,
                     method="highs")
    return result.status == 0


def statics_limit(facets, kappa):
    low, high = 0.5, 3.
    while high - low > 1e-7:
        middle = 0.5 * (low + high)
        if admissible(middle, facets, kappa):
            low = middle
        else:
            high = middle
    return low


def hoek_bray():
    n1, n2 = (normal(*p) for p in PLANES)
    line = np.cross(n1, n2)
    line /= np.linalg.norm(line)
    if line[2] > 0.:
        line = -line  # downhill
    weight = np.array([0., 0., -1.])
    across = weight - weight.dot(line) * line
    forces = np.linalg.lstsq(np.array([n1, n2]).T, -across, rcond=None)[0]
    plunge = math.degrees(math.asin(-line[2]))
    return TAN_PHI * forces.sum() / weight.dot(line), plunge, line


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--facets", type=int, default=720)
    args = parser.parse_args()
    f_hb, plunge, line = hoek_bray()
    print("line of intersection (%.4f, %.4f, %.4f), plunge %.2f deg"
          % (*line, plunge))
    print("Hoek and Bray (shear along the line):  F = %.5f" % f_hb)
    upper = statics_limit(args.facets, 1.)
    lower = statics_limit(args.facets, math.cos(math.pi / args.facets))
    print("statics, %d facets, circumscribed:     F = %.5f" % (args.facets,
                                                             upper))
    print("statics, %d facets, inscribed:         F = %.5f" % (args.facets,
                                                             lower))
    print("statics limit / Hoek and Bray = %.4f" % (upper / f_hb))


if __name__ == "__main__":
    main()
