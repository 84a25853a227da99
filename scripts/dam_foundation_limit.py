#!/usr/bin/python3
"""Limit equilibrium of parameters/dam_foundation.prm (issue 28, part 4):
the two sliding paths of a gravity dam on a jointed rock foundation,
rigid blocks, the loads of the parameter file at t = 3 (full reservoir,
full uplift), each joint's strength divided by F:

  (a) the dam alone on its construction joint (y = 0, 0 <= x <= 80):
      F_a = (c_a A_a + (W_dam - U_a) tan(phi_a)) / H
  (b) dam and rock wedge together on the rock joint (from (-10,-12) to
      (110,-4), rising downstream at alpha = atan(8/120)), the water in
      the crack upstream of the wedge pushing it:
      F_b = (c_b A_b + N tan(phi_b)) / T, with T and N the resultant of
      weights, water on the dam face, in the crack and on the wedge top,
      along and normal to the joint, N less the uplift U_b.

  /usr/bin/python3 scripts/dam_foundation_limit.py

prints both, and which path governs. The numbers below must match the
parameter file (they are its constants).
"""
import math

GAMMA_W = 10e3        # water, N/m^3
LEVEL = 95.0          # reservoir level, m
GAMMA_DAM, GAMMA_ROCK = 24e3, 26e3
DAM_BASE, DAM_HEIGHT = 80.0, 100.0
DRAIN_X, DRAIN_RATIO = 8.0, 1.0 / 3.0     # drainage gallery
CRACK_DEPTH = 12.0                        # wedge face in the crack
JOINT = ((-10.0, -12.0), (110.0, -4.0))   # the rock joint
WEDGE = [(-10.0, 0.0), (110.0, 0.0), (110.0, -4.0), (-10.0, -12.0)]
C_A, TANPHI_A = 400e3, 1.0                 # construction joint
C_B, TANPHI_B = 50e3, math.tan(math.radians(40.0))  # rock joint


def area(poly):
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1)
                         in zip(poly, poly[1:] + poly[:1])))


def main():
    w_dam = GAMMA_DAM * 0.5 * DAM_BASE * DAM_HEIGHT
    h = 0.5 * GAMMA_W * LEVEL ** 2
    p_heel = GAMMA_W * LEVEL
    p_drain = DRAIN_RATIO * p_heel
    u_a = 0.5 * (p_heel + p_drain) * DRAIN_X + 0.5 * p_drain * (DAM_BASE - DRAIN_X)
    f_a = (C_A * DAM_BASE + (w_dam - u_a) * TANPHI_A) / h
    print("(a) construction joint: W = %.6g, H = %.6g, U = %.6g N/m: F_a = %.6f"
          % (w_dam, h, u_a, f_a))

    w_wedge = GAMMA_ROCK * area(WEDGE)
    top = p_heel * 10.0                      # water on the wedge top, x in [-10, 0]
    crack = GAMMA_W * (LEVEL * CRACK_DEPTH + 0.5 * CRACK_DEPTH ** 2)
    (x0, y0), (x1, y1) = JOINT
    length = math.hypot(x1 - x0, y1 - y0)
    alpha = math.atan2(y1 - y0, x1 - x0)
    u_b = 0.5 * GAMMA_W * (LEVEL - y0) * length
    fx, fy = h + crack, -(w_dam + w_wedge + top)
    t = fx * math.cos(alpha) + fy * math.sin(alpha)
    n = -(-fx * math.sin(alpha) + fy * math.cos(alpha)) - u_b
    f_b = (C_B * length + n * TANPHI_B) / t
    print("(b) rock joint, alpha = %.4f deg: W_wedge = %.6g, crack %.6g, top "
          "%.6g, U = %.6g N/m; T = %.6g, N' = %.6g: F_b = %.6f"
          % (math.degrees(alpha), w_wedge, crack, top, u_b, t, n, f_b))
    print("the failure path runs along the %s (F = %.6f)"
          % ("rock joint" if f_b < f_a else "construction joint", min(f_a, f_b)))


if __name__ == "__main__":
    main()
