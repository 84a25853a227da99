#!/usr/bin/env bash
# Issue 62, part 2: De Saxce's fixed point of convex QPs
# (scripts/desaxce_fixed_point_2d.py) solves the increment that mbfem's
# chain without Newton's method gives up on: Goodman and Bray's column at
# 0.985 of its limit (tests/failures/solver_gives_up_writes_problem.prm,
# exit code 3, its problem written). The relaxed fixed point (omega = 0.5)
# must settle on a solution of the joint law (violations below 1e-7,
# checked by check_contact_problem_2d.py's check()); the unrelaxed one
# (omega = 1) must not settle within 100 QPs: it oscillates, which is why
# the relaxation is there.
# Usage: desaxce_column.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cp "$source_dir/tests/failures/solver_gives_up_writes_problem.prm" \
   "$source_dir/tests/failures/lemke_secondary_ray.prm" . || exit 1
sed -i "s#\.\./\.\./meshes/#$source_dir/meshes/#" lemke_secondary_ray.prm
"$mbfem" solver_gives_up_writes_problem.prm > column.log 2>&1
status=$?
[ $status -eq 3 ] || { echo "FAIL: mbfem exited with $status, not 3"; tail -5 column.log; exit 1; }
problem=results/toppling_column-failed-problem-0001.json
script=$source_dir/scripts/desaxce_fixed_point_2d.py
/usr/bin/python3 "$script" "$problem" > relaxed.log 2>&1
status=$?
cat relaxed.log
[ $status -eq 0 ] || { echo "FAIL: the relaxed fixed point exited with $status, not 0"; exit 1; }
grep -q "^verdict: a solution exists" relaxed.log || { echo "FAIL: no solution found"; exit 1; }
/usr/bin/python3 "$script" "$problem" --omega 1 --iterations 100 > plain.log 2>&1
status=$?
tail -1 plain.log
[ $status -eq 1 ] || { echo "FAIL: the unrelaxed fixed point exited with $status, not 1 (undecided)"; exit 1; }
echo "PASS: the increment mbfem's chain gives up on has a solution, found by the relaxed fixed point"
