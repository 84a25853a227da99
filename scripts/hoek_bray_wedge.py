#!/usr/bin/env python3
"""Hoek and Bray's factor of safety of a dry, cohesionless wedge on two
planes, for parameters/rock_slope_wedge.prm (issue 61), computed
independently of mbfem, two ways:

1. Hoek and Bray's formula (Rock Slope Engineering, the wedge with
   friction only): F = A tan(phi_A) + B tan(phi_B),
     A = (cos psi_a - cos psi_b cos t) / (sin psi_i sin^2 t),
     B = (cos psi_b - cos psi_a cos t) / (sin psi_i sin^2 t),
   psi_a, psi_b the planes' dips, psi_i the plunge of their line of
   intersection, t the angle between their normals.
2. The statics of the rigid wedge sliding along the line of intersection:
   the weight split into the normal forces N_A, N_B and the component S
   along the line, F = (N_A tan(phi_A) + N_B tan(phi_B)) / S.

It also prints the wedge's corners and volume in the slope of the .prm
(flat crest, face dipping towards +x), so that one can check that the
wedge daylights and stays inside the model.

  /usr/bin/python3 scripts/hoek_bray_wedge.py
"""
import math

import numpy as np


def normal(dip, dip_direction):
    """Upward unit normal; x east, y north, z up."""
    d, a = math.radians(dip), math.radians(dip_direction)
    return np.array([math.sin(d) * math.sin(a), math.sin(d) * math.cos(a),
                     math.cos(d)])


def hoek_bray(plane_a, plane_b, phi_a, phi_b):
    na, nb = normal(*plane_a), normal(*plane_b)
    line = np.cross(na, nb)
    line /= np.linalg.norm(line)
    if line[2] > 0:
        line = -line                      # downwards, the sliding direction
    plunge = math.asin(-line[2])
    cos_t = na @ nb
    sin2_t = 1. - cos_t**2
    ca, cb = math.cos(math.radians(plane_a[0])), math.cos(math.radians(plane_b[0]))
    A = (ca - cb * cos_t) / (math.sin(plunge) * sin2_t)
    B = (cb - ca * cos_t) / (math.sin(plunge) * sin2_t)
    ta, tb = math.tan(math.radians(phi_a)), math.tan(math.radians(phi_b))
    formula = A * ta + B * tb
    # unit weight (0, 0, -1) = -(N_A na + N_B nb) + S line
    n_a, n_b, s = np.linalg.solve(np.column_stack([na, nb, line]),
                                  np.array([0., 0., -1.]))
    n_a, n_b = -n_a, -n_b
    statics = (n_a * ta + n_b * tb) / s
    trend = math.degrees(math.atan2(line[0], line[1])) % 360.
    return dict(A=A, B=B, plunge=math.degrees(plunge), trend=trend,
                N_A=n_a, N_B=n_b, S=s, formula=formula, statics=statics)


def wedge(plane_a, plane_b, point, height, face_angle, crest_width):
    """Corners of the wedge under a flat crest at z = height and a face
    dipping face_angle towards +x through (crest_width, *, height)."""
    na, nb = normal(*plane_a), normal(*plane_b)
    f = math.radians(face_angle)
    nf, nc = np.array([math.sin(f), 0., math.cos(f)]), np.array([0., 0., 1.])
    face = np.array([crest_width, 0., height])
    crest = np.array([0., 0., height])
    o = np.array(point)

    def meet(planes):
        return np.linalg.solve(np.array([n for n, _ in planes]),
                               np.array([n @ p for n, p in planes]))
    c = meet([(na, o), (nb, o), (nc, crest)])
    pa = meet([(na, o), (nf, face), (nc, crest)])
    pb = meet([(nb, o), (nf, face), (nc, crest)])
    volume = abs(np.linalg.det(np.array([c - o, pa - o, pb - o]))) / 6.
    return dict(O=o, C=c, P_A=pa, P_B=pb, volume=volume)


if __name__ == "__main__":
    A, B = (45., 10.), (70., 140.)
    r = hoek_bray(A, B, 20., 30.)
    print("planes A %g/%g, B %g/%g, phi 20 and 30 deg, c = 0, dry" % (A + B))
    print("line of intersection: plunge %.4f towards %.4f" %
          (r["plunge"], r["trend"]))
    print("A = %.5f, B = %.5f: F = %.6f (Hoek and Bray)" %
          (r["A"], r["B"], r["formula"]))
    print("rigid wedge along the line: N_A = %.5f W, N_B = %.5f W, "
          "S = %.5f W: F = %.6f" % (r["N_A"], r["N_B"], r["S"], r["statics"]))
    w = wedge(A, B, (25.12938424, 20., 1.), 12., 65., 20.)
    for k in ("O", "C", "P_A", "P_B"):
        print("  %-3s = (%.3f, %.3f, %.3f)" % ((k,) + tuple(w[k])))
    print("  volume %.3f m^3" % w["volume"])
