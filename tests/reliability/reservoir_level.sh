#!/usr/bin/env bash
# Issue 63: a random constant of the functions (the reservoir level h of
# parameters/gravity_dam_level_reliability.prm, sampled alone: the
# friction stays tan(phi) = 1), named in two functions at once: the traction on the dam's upstream face,
# pw max(h - y, 0) t, and the drained uplift in its foundation joint (pw h
# at the heel, a third of it at the drain 5 m downstream, 0 at the toe).
# The dam of parameters/gravity_dam_safety.prm (W = 8640 kN/m, tan(phi) =
# 1, c = 0): H = pw h^2 / 2, U = 6.5 pw h, so each sample's factor of
# safety must be (W - 6.5 pw h) / (pw h^2 / 2) within the search's
# tolerance (1e-3 below, a bisected bracket; 2.5e-4 above, the statics
# bound's). h uniform in [20, 30] m, 12 Monte Carlo samples (seed 5). A
# constant no function names is refused (tests/failures/
# reliability_unknown_constant.prm).
# Usage: reservoir_level.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cat > level.prm <<PRM
include $source_dir/parameters/gravity_dam_level_reliability.prm
set Test mode = true
subsection Reliability
  set Random variables  = h: constant h, uniform min 20 max 30
  set Method            = sampling
  set Number of samples = 12
  set Seed              = 5
end
subsection Output
  set Base name = level
end
PRM
"$mbfem" level.prm > screen.txt 2>&1 || { cat screen.txt; echo "FAIL: mbfem"; exit 1; }
sed -n '/^Reliability:/,$p' screen.txt
python3 - <<'PY'
import csv, sys
rows = list(csv.DictReader(open("results/level-reliability.csv")))
worst_low = worst_high = 0.
for r in rows:
    h, F = float(r["h"]), float(r["F"])
    exact = (8640e3 - 6.5 * 10e3 * h) / (10e3 * h * h / 2.)
    worst_low = min(worst_low, F / exact - 1.)
    worst_high = max(worst_high, F / exact - 1.)
print(f"{len(rows)} samples: F / closed form - 1 in [{worst_low:.2e}, {worst_high:.2e}]")
ok = len(rows) == 12 and worst_low >= -1e-3 and worst_high <= 2.5e-4
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
PY
