#!/usr/bin/env bash
# Issue 28, part 3: the reservoir in stages against one stage, on the
# gravity dam of parameters/gravity_dam.prm (FE_Q(1)). Both load histories
# end with the same loads (full self-weight, water 25 m deep):
#   one stage:  self-weight and water rising to 25 m together, 5 increments;
#   stages:     'self weight: 1, 1; filling: 2, 5; drawdown: 3, 2': the
#               weight first, then the water to 30 m, then down to 25 m.
# With a joint that cannot slip or open (mu = 5, c and sigma_t 5 MPa) the
# interface problem is linear and the final states, forces and tangential
# relative displacements must agree to round-off: 1e-8 of the largest, or
# of 1 micrometre where they are all round-off (stuck from the start, the
# pairs' tangential displacements are 1e-17 m here, against slips of the
# order of 1e-4 m when the joint slips). With mu = 0.6 and
# c = 0 the joint slips while the water rises to 30 m (13 of 25 pairs) and
# sticks again as it falls: the slip stays, and the final tangential
# relative displacements must differ by more than 1e-3 of the largest.
# The script exits non-zero otherwise.
# Usage: compare.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

write() { # name, joint lines, stage lines
  cat > "$1.prm" <<PRM
include $source_dir/parameters/gravity_dam.prm
set Test mode = true
subsection Finite element
  set Polynomial degree = 1
end
subsection Contact
$2
end
subsection Output
  set Directory = $work/$1
end
$3
PRM
}
one_stage='subsection Boundary conditions
  set Gravity ramp time = 1
  subsection Traction
    set Function expression = 10e3 * max(25 * t - y, 0); 0
  end
end'
staged='subsection Boundary conditions
  set Gravity ramp time = 1
  subsection Traction
    set Function expression = 10e3 * max(30 * min(max(t - 1, 0), 1) - 5 * min(max(t - 2, 0), 1) - y, 0); 0
  end
end
subsection Load history
  set Number of increments = 1
  set Stages               = self weight: 1, 1; filling: 2, 5; drawdown: 3, 2
end'
stick='  set Friction coefficient = 5
  set Cohesion             = 5e6
  set Tensile strength     = 5e6'
slip='  set Friction coefficient = 0.6'

write stick_one "$stick" "$one_stage"
write stick_staged "$stick" "$staged"
write slip_one "$slip" "$one_stage"
write slip_staged "$slip" "$staged"
failed=0
for run in stick_one stick_staged slip_one slip_staged; do
  "$mbfem" $run.prm > $run.log 2>&1 || { echo "FAIL: mbfem $run.prm"; tail -5 $run.log; failed=1; }
done
[ $failed -eq 0 ] || exit 1
grep -h "stage" stick_staged.log | head -3

/usr/bin/python3 - "$work" <<'PY' || failed=1
import csv, glob, sys
work = sys.argv[1]

def last_pairs(run):
    name = sorted(glob.glob("%s/%s/*-pairs-*.csv" % (work, run)))[-1]
    rows = [l for l in open(name) if not l.startswith("#")]
    return name, list(csv.DictReader(rows))

def difference(a, b, columns):
    _, ra = last_pairs(a)
    _, rb = last_pairs(b)
    largest = max(max(abs(float(r[c])) for r in ra + rb) for c in columns)
    diff = max(abs(float(x[c]) - float(y[c])) for x, y in zip(ra, rb)
               for c in columns)
    floor = 1e-6 if columns == ("slip_1",) else 1e-300  # 1 micrometre
    return diff / max(largest, floor)

def states(a, b):
    _, ra = last_pairs(a)
    _, rb = last_pairs(b)
    return (sum(x["state"] != y["state"] for x, y in zip(ra, rb)),
            [r["state"] for r in ra].count("slip"))

forces = ("normal_force", "tangential_force_1")
ok = True
f = difference("stick_one", "stick_staged", forces)
d = difference("stick_one", "stick_staged", ("slip_1",))
s, n_slip = states("stick_one", "stick_staged")
same = f < 1e-8 and d < 1e-8 and s == 0
print("no slip (mu = 5): final forces differ by %.2e, tangential relative "
      "displacements by %.2e of the largest, states at %d pairs, %d pairs "
      "slipping: %s" % (f, d, s, n_slip, "same" if same else "DIFFERENT"))
ok = ok and same
f = difference("slip_one", "slip_staged", forces)
d = difference("slip_one", "slip_staged", ("slip_1",))
s, n_slip = states("slip_one", "slip_staged")
print("slip (mu = 0.6): final forces differ by %.2e, slips by %.2e of the "
      "largest, states at %d pairs, %d pairs slipping: %s"
      % (f, d, s, n_slip, "different" if d > 1e-3 else "SAME"))
ok = ok and d > 1e-3
sys.exit(0 if ok else 1)
PY
[ $failed -eq 0 ] && echo "PASS: one stage and stages agree without slip and differ with it"
exit $failed
