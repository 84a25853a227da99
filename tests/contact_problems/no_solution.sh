#!/usr/bin/env bash
# Issue 27: is an exit code 3 the solver's failure or the model's? The
# 30 m dam with c = 200 kPa, phi = 35 deg and full uplift, at the
# strength-reduction factor F = 1.60679 where its trial failed
# (tests/srm_dam_cohesion_uplift): the load path of increment 5 holds to
# s = 0.9992, breaking the heel's pairs; rigid-block statics with the whole
# base admits forces, without the broken pairs' cohesion none, so mbfem ends
# with exit code 2 (doc/decisions.md, "Joints the load path broke"; exit
# code 3 before) and writes the increment's problem.
# scripts/check_contact_problem_2d.py, an exact mixed-integer formulation
# of the joint law on the increment's one-shot problem, must agree that it
# has no solution (exit 2): the heel opens and loses its cohesion, and the
# 18.5 m of joint left closed cannot carry the thrust. On the converged
# increment 4 of the same run it must find one (exit 0).
# Usage: no_solution.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cat > dam.prm <<PRM
include $source_dir/parameters/gravity_dam_safety.prm
set Test mode = true
set Mode      = simulation
subsection Finite element
  set Polynomial degree = 1
end
subsection Contact
  set Friction coefficient = 0.43578036844   # tan(35 deg) / 1.60679
  set Cohesion             = 124471.77291    # 200 kPa / 1.60679
end
subsection Water pressure
  set Function expression = 10e3 * 30 * max(1 - x / 24, 0) * t
end
subsection Strength reduction
  set Closed-form factor of safety =
end
subsection Output
  set Directory              = $work/results
  set Write VTU              = false
  set Write contact problems = true
end
PRM
"$mbfem" dam.prm > dam.log 2>&1
status=$?
[ $status -eq 2 ] || { echo "FAIL: mbfem exited with $status, not 2"; tail -5 dam.log; exit 1; }
grep -q "once the joints the load path broke have lost their strength" dam.log ||
  { echo "FAIL: mbfem's exit code 2 is not the verdict after the load path's breaking"; exit 1; }
check=$source_dir/scripts/check_contact_problem_2d.py
/usr/bin/python3 "$check" results/gravity_dam_safety-failed-problem-0005.json
status=$?
[ $status -eq 2 ] || { echo "FAIL: increment 5: the check exited with $status, not 2 (no solution)"; exit 1; }
/usr/bin/python3 "$check" results/gravity_dam_safety-problem-0004.json > inc4.log
status=$?
tail -1 inc4.log
[ $status -eq 0 ] || { echo "FAIL: increment 4: the check exited with $status, not 0"; cat inc4.log; exit 1; }
echo "PASS: increment 5 has no solution (as mbfem's exit code 2 says), increment 4 has one"
