#!/usr/bin/env bash
# Issue 63: FORM (Reliability/Method = FORM, OpenTURNS' FORM with Cobyla)
# on the dam, against closed forms.
# 1. parameters/gravity_dam_reliability.prm with FORM: one variable, the
#    limit state F = 6690 tan(phi) / 4500 = 1 at phi* = atan(4500 / 6690) =
#    33.9266 deg, beta = -Phi^-1(P(phi < phi*)) = 1.21481 for the truncated
#    normal (40, 5) in [20, 60]. Asked: phi* and beta within 1e-3 relative
#    (each evaluation's F is the middle of a search bracket 1e-3 wide).
# 2. parameters/gravity_dam_level_reliability.prm: phi truncated normal
#    (36, 4) in [20, 60] and the reservoir level h uniform in [20, 30] m, a
#    constant of the traction and the uplift:
#    F = (W - 6.5 pw h) tan(phi) / (pw h^2 / 2). The reference is the same
#    FORM on that closed form with scipy (SLSQP in the standard space,
#    independent marginals): beta within 1e-3 relative, the design point
#    within 5e-3, the importance factors within 0.02 (Cobyla stops on the
#    limit state to its tolerance; the direction of the design point is
#    less sharply defined than its distance).
# Usage: form.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cat > one.prm <<PRM
include $source_dir/parameters/gravity_dam_reliability.prm
set Test mode = true
subsection Reliability
  set Method = FORM
end
subsection Output
  set Base name = one
end
PRM
cat > two.prm <<PRM
include $source_dir/parameters/gravity_dam_level_reliability.prm
set Test mode = true
subsection Output
  set Base name = two
end
PRM
for run in one two; do
  "$mbfem" $run.prm > $run.txt 2>&1 || { cat $run.txt; echo "FAIL: $run"; exit 1; }
  sed -n '/FORM: design/,/evaluations/p' $run.txt
done
/usr/bin/python3 - <<'PY'
import math, re, sys
import numpy as np
from scipy.optimize import minimize
from scipy.stats import norm, truncnorm

def found(name):
    text = open(name + ".txt").read()
    design = [float(x) for x in re.findall(r"= ([-0-9.e+]+)", re.search(r"FORM: design point(.*)", text).group(1))]
    beta = float(re.search(r"beta = ([-0-9.e+]+)", text).group(1))
    importance = [float(x) for x in re.findall(r" [a-z]+ ([0-9.e+-]+)", re.search(r"importance factors:(.*)", text).group(1))]
    return design, beta, importance

ok = True
# 1. One variable, closed form.
d, beta, _ = found("one")
phi_star = math.degrees(math.atan(4500. / 6690.))
a, b = (20 - 40) / 5., (60 - 40) / 5.
exact = -norm.ppf(truncnorm.cdf(phi_star, a, b, loc=40, scale=5))
print(f"one: phi* {d[0]} (exact {phi_star:.6f}), beta {beta} (exact {exact:.6f})")
ok &= abs(d[0] / phi_star - 1) < 1e-3 and abs(beta / exact - 1) < 1e-3

# 2. Two variables, FORM on the closed form.
a, b = (20 - 36) / 4., (60 - 36) / 4.
def physical(u):
    return (truncnorm.ppf(norm.cdf(u[0]), a, b, loc=36, scale=4),
            20 + 10 * norm.cdf(u[1]))
def g(u):
    phi, h = physical(u)
    return (8640 - 65 * h) * math.tan(math.radians(phi)) / (5 * h * h) - 1
r = minimize(lambda u: u @ u, np.array([-0.5, 0.5]), method="SLSQP",
             constraints=[{"type": "eq", "fun": g}],
             options={"ftol": 1e-14, "maxiter": 500})
ref_beta = float(np.linalg.norm(r.x))
ref_design = physical(r.x)
ref_importance = r.x ** 2 / ref_beta ** 2
d, beta, importance = found("two")
print(f"two: design {d} (reference {ref_design[0]:.5f}, {ref_design[1]:.5f}), "
      f"beta {beta} (reference {ref_beta:.6f}), importance {importance} "
      f"(reference {ref_importance[0]:.4f}, {ref_importance[1]:.4f})")
ok &= abs(beta / ref_beta - 1) < 1e-3
ok &= all(abs(x / y - 1) < 5e-3 for x, y in zip(d, ref_design))
ok &= all(abs(x - y) < 0.02 for x, y in zip(importance, ref_importance))
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
PY
