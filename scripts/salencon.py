#!/usr/bin/python3
"""Salencon's closed form for a circular opening of radius a, unlined
(p_i = 0), in elastic-perfectly plastic Mohr-Coulomb rock under a
hydrostatic in-situ stress p0 (plane strain, small strains, non-associated
flow with dilatancy psi), for a ring a <= r <= b whose outer boundary keeps
the in-situ traction p0 (b -> infinity gives the textbook case; a finite b
only changes the elastic zone, which is a thick ring here).

  /usr/bin/python3 scripts/salencon.py a b p0 E nu c phi psi

prints the plastic radius R, the wall displacement u(a), the yielded area
of a quarter model, and muParser expressions of the exact displacement and
stress (tension positive, changes of displacement from the in-situ state)
for 'Exact solution' in a .prm.
"""
import math
import sys

a, b, p0, E, nu, c, phi, psi = map(float, sys.argv[1:9])
G = E / (2 * (1 + nu))
K = (1 + math.sin(math.radians(phi))) / (1 - math.sin(math.radians(phi)))
m = (1 + math.sin(math.radians(psi))) / (1 - math.sin(math.radians(psi)))
sc = 2 * c * math.cos(math.radians(phi)) / (1 - math.sin(math.radians(phi)))
D = sc / ((K - 1) * a ** (K - 1))  # p_i = 0


def outer_stress(R):
    """sigma_r(b) (compression positive) of the elastic ring R..b."""
    s_re = D * R ** (K - 1) - sc / (K - 1)
    A = ((K + 1) * s_re + sc) / 2
    B = R * R * ((K - 1) * s_re + sc) / 2
    return A - B / b ** 2, A, B, s_re


lo, hi = a, b
for _ in range(200):
    mid = 0.5 * (lo + hi)
    if outer_stress(mid)[0] < p0:
        lo = mid
    else:
        hi = mid
R = 0.5 * (lo + hi)
_, A, B, s_re = outer_stress(R)
if R <= a * (1 + 1e-12):
    sys.exit("the rock stays elastic")

P = p0 + sc / (K - 1)
alpha = (1 + m) * (1 - 2 * nu) * P / (2 * G)
beta = -D * ((1 - nu) - nu * K + m * ((1 - nu) * K - nu)) / (2 * G)


def u_elastic(r):
    return r / (2 * G) * ((1 - 2 * nu) * (p0 - A) - B / r ** 2)


def u(r):
    if r >= R:
        return u_elastic(r)
    return r ** (-m) * (R ** m * u_elastic(R)
                        - alpha * (R ** (m + 1) - r ** (m + 1)) / (m + 1)
                        - beta * (R ** (m + K) - r ** (m + K)) / (m + K))


print("K = %.10g, m = %.10g, sigma_c = %.10g" % (K, m, sc))
print("plastic radius R = %.10g (R/a = %.6f)" % (R, R / a))
print("radial stress at R: %.10g (compression)" % s_re)
print("wall displacement u(a) = %.10g (inward)" % u(a))
print("yielded area of a quarter model = %.10g" % (math.pi / 4 * (R * R - a * a)))
consts = ("R=%.15g, G=%.15g, nu=%.15g, p0=%.15g, A=%.15g, B=%.15g, D=%.15g, K=%.15g, "
          "m=%.15g, sc=%.15g, al=%.15g, be=%.15g, uR=%.15g"
          % (R, G, nu, p0, A, B, D, K, m, sc, alpha, beta, u_elastic(R)))
rr = "sqrt(x^2+y^2)"
ur = ("if({r} >= R, {r}/(2*G)*((1-2*nu)*(p0-A) - B/{r}^2), "
      "{r}^(-m)*(R^m*uR - al*(R^(m+1)-{r}^(m+1))/(m+1) - be*(R^(m+K)-{r}^(m+K))/(m+K)))").format(r=rr)
sr = "if({r} >= R, -(A - B/{r}^2), -(D*{r}^(K-1) - sc/(K-1)))".format(r=rr)
st = "if({r} >= R, -(A + B/{r}^2), -(K*D*{r}^(K-1) - sc/(K-1)))".format(r=rr)
print("\nFunction constants  = " + consts)
print("Displacement: t*(%s)*x/%s; t*(%s)*y/%s" % (ur, rr, ur, rr))
print("Stress: (%s)*x^2/(x^2+y^2) + (%s)*y^2/(x^2+y^2); ((%s)-(%s))*x*y/(x^2+y^2); "
      "((%s)-(%s))*x*y/(x^2+y^2); (%s)*y^2/(x^2+y^2) + (%s)*x^2/(x^2+y^2)"
      % (sr, st, sr, st, sr, st, sr, st))
