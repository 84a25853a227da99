#!/usr/bin/env bash
# Issue 27, part 4: the contact problems mbfem writes, read back without
# mbfem (scripts/read_contact_problem.py). Four models:
#   - the paper's 3D stacked cantilevers at p = 1 (105 pairs, stick, slip
#     and open pairs, no floating block), every one of its 10 increments;
#   - the 2D incline block with water and cohesion at F = 1 (9 pairs, one
#     floating block: G and f, slipping and stuck pairs);
#   - the 3D incline block pushed along the strike at 0.95 of its limit
#     (tests/state_incline_45_3d_095: 81 pairs, 77 slipping in a direction
#     solved for, one floating block);
#   - the 30 m dam with tan(phi) = 1 (increments where every pair sticks,
#     so that u is round-off, then slip as the water rises).
# For each increment u = W r + q + G alpha and G^T r + f = 0 must hold, and
# the forces solved again from the states found must equal mbfem's, to
# 1e-10 relative to the largest; the joint law pair by pair to 1e-8. The
# script exits non-zero otherwise.
# Usage: read_back.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

cat > stacked.prm <<PRM
include $source_dir/parameters/stacked_cantilevers.prm
set Test mode = true
subsection Mesh
  set Generator arguments = 20,4,4 : 0,0,0 : 10,2,2 : true
end
subsection Finite element
  set Polynomial degree = 1
end
subsection Contact
  set Formulation = condensed
end
subsection Output
  set Directory              = $work/stacked
  set Write VTU              = false
  set Write contact problems = true
end
PRM
cat > incline.prm <<PRM
include $source_dir/parameters/incline_uplift.prm
set Test mode = true
set Mode      = simulation
subsection Contact
  set Cohesion = 10e3
end
subsection Strength reduction
  set Closed-form factor of safety =
end
subsection Output
  set Directory              = $work/incline
  set Write contact problems = true
end
PRM

sed "s#@SOURCE_DIR@#$source_dir/tests#" \
  "$source_dir/tests/state_incline_45_3d_095.prm.in" > incline3d.prm
cat >> incline3d.prm <<PRM
subsection Output
  set Directory              = $work/incline3d
  set Write contact problems = true
end
PRM
cat > dam.prm <<PRM
include $source_dir/parameters/gravity_dam.prm
set Test mode = true
subsection Finite element
  set Polynomial degree = 1
end
subsection Contact
  set Friction coefficient = 1
end
subsection Output
  set Directory              = $work/dam
  set Write contact problems = true
end
PRM

failed=0
for model in stacked incline incline3d dam; do
  if ! "$mbfem" $model.prm > $model.log 2>&1; then
    echo "FAIL: mbfem $model.prm"; tail -5 $model.log; failed=1; continue
  fi
  n=0
  for problem in "$model"/*-problem-*.json; do
    n=$((n + 1))
    /usr/bin/python3 "$source_dir/scripts/read_contact_problem.py" "$problem" \
      || failed=1
  done
  [ $n -gt 0 ] || { echo "FAIL: $model wrote no contact problem"; failed=1; }
done
[ $failed -eq 0 ] && echo "PASS: every problem read back"
exit $failed
