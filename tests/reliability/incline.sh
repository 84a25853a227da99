#!/usr/bin/env bash
# Issue 63: 'Mode = reliability' on inclined blocks with closed forms.
#
# 1. The block of parameters/incline_6deg.prm (slope 6.57 deg, no cohesion),
#    its friction angle phi truncated normal (mean 8, sd 1.5, in [1, 20]),
#    400 Monte Carlo samples (seed 7): each sample's F must be Coulomb's
#    tan(phi) / tan(6.57 deg) to the search's tolerance (the bracket's lower
#    end, F_LP (1 - 5e-4), and not above F_LP (1 + 2.5e-4)); its verdict at
#    F = 1 must be 'fails' exactly where phi < 6.57 deg; and the exact
#    P(phi < 6.57) of the truncated normal, 0.17021, must lie in the 95 %
#    interval printed (a fixed seed: the interval holds it for this draw).
# 2. The block of parameters/incline_uplift.prm (24.2 deg, 2.26 m base,
#    W = 95485 N/m, FE_Q(1), 9 pairs) dry, phi truncated normal (30, 4, in
#    [10, 50]) and a lognormal cohesion (mean 10 kPa, cov 0.5) with a rank
#    correlation of -0.5, 60 samples of a Latin hypercube (seed 3): the
#    drawn ranks must correlate within 0.15 of -0.5 (the sampling error of
#    Spearman's coefficient for 60 pairs is about 0.1); each F must lie
#    between the rigid block's (c A + N tan(phi)) / T with the cohesion of
#    one end pair lost (A - 2.26/16: with enough cohesion the pair at the
#    upper corner opens and breaks on the way to the limit) and that with
#    all of A (the statics bound), to the search's tolerance (a bisected
#    bracket is 1e-3 wide, so F may lie up to 1e-3 below the limit; the
#    statics bound's bracket ends 2.5e-4 above it).
# Usage: incline.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

cat > friction.prm <<PRM
include $source_dir/parameters/incline_6deg.prm
set Mode = reliability
set Test mode = true
subsection Reliability
  set Random variables  = phi: interface 1 friction angle, truncated normal mean 8 sd 1.5 min 1 max 20
  set Number of samples = 400
  set Seed              = 7
end
subsection Output
  set Base name = friction
end
PRM
cat > cohesion.prm <<PRM
include $source_dir/parameters/incline_uplift.prm
set Mode = reliability
set Test mode = true
subsection Water pressure
  set Interfaces          =
  set Function expression = 0
end
subsection Strength reduction
  set Closed-form factor of safety =
end
subsection Reliability
  set Random variables  = phi: all friction angle, truncated normal mean 30 sd 4 min 10 max 50; c: all cohesion, lognormal mean 10e3 cov 0.5
  set Rank correlation  = phi c -0.5
  set Sampling          = Latin hypercube
  set Number of samples = 60
  set Seed              = 3
end
subsection Output
  set Base name = cohesion
  set Write VTU = false
end
PRM
fail=0
for run in friction cohesion; do
  "$mbfem" $run.prm > $run.txt 2>&1 || { cat $run.txt; echo "FAIL: $run"; exit 1; }
  sed -n '/^Reliability:/,/estimates in/p' $run.txt
done
python3 - <<'PY' || fail=1
import csv, math, re, sys
ok = True
def rows(name):
    return list(csv.DictReader(open(f"results/{name}-reliability.csv")))

# 1. Coulomb on the 6.57 deg incline.
t = math.tan(math.radians(6.57))
worst, wrong = 0., 0
for r in rows("friction"):
    phi = float(r["phi"])
    exact = math.tan(math.radians(phi)) / t
    worst = max(worst, abs(float(r["F"]) / exact - 1.))
    if abs(phi - 6.57) > 1e-3:
        wrong += (r["verdict"] == "fails") != (phi < 6.57)
Phi = lambda x: 0.5 * (1. + math.erf(x / math.sqrt(2.)))
z = lambda x: (x - 8.) / 1.5
p = (Phi(z(6.57)) - Phi(z(1.))) / (Phi(z(20.)) - Phi(z(1.)))
line = open("friction.txt").read()
lo, hi = map(float, re.search(r"95 % interval \[([^,]+), ([^\]]+)\]", line).groups())
print(f"friction: worst |F / (tan(phi)/tan(theta)) - 1| = {worst:.2e}, "
      f"verdicts against phi < 6.57: {wrong} wrong; exact P = {p:.5f} "
      f"in [{lo}, {hi}]")
# 5e-4: the bracket F_LP (1 - 5e-4); 1e-7: the LP and the ten digits of the CSV.
ok &= worst <= 5e-4 + 1e-7 and wrong == 0 and lo <= p <= hi

# 2. Cohesion and friction, correlated.
W, theta, A = 95485., math.radians(24.2), 2.26
r2 = rows("cohesion")
def rank(x):
    order = sorted(range(len(x)), key=lambda i: x[i])
    r = [0] * len(x)
    for k, i in enumerate(order):
        r[i] = k
    return r
a = rank([float(r["phi"]) for r in r2])
b = rank([float(r["c"]) for r in r2])
n = len(a)
rho = 1. - 6. * sum((x - y) ** 2 for x, y in zip(a, b)) / (n * (n * n - 1))
outside = 0
for r in r2:
    phi, c, F = float(r["phi"]), float(r["c"]), float(r["F"])
    N, T = W * math.cos(theta), W * math.sin(theta)
    whole = (c * A + N * math.tan(math.radians(phi))) / T
    lost = (c * (A - A / 16.) + N * math.tan(math.radians(phi))) / T
    outside += not (lost * (1 - 1e-3) * (1 - 1e-9) <= F <= whole * (1 + 2.5e-4) * (1 + 1e-9))
print(f"cohesion: rank correlation {rho:.4f} (asked -0.5), "
      f"{outside} of {n} factors outside [lost end pair, whole joint]")
ok &= abs(rho + 0.5) <= 0.15 and outside == 0
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
PY
exit $fail
