#!/usr/bin/env bash
# Issue 27, part 2: Goodman and Bray's column (parameters/toppling_column.prm)
# just below its limit-equilibrium factor F = 2.039446, the weight in one
# increment: at 0.9807 (mu = 0.5) and 0.985 of the limit (mu = 1/(0.985 F))
# the fast iteration, the load path and Newton's method without springs
# fail, and Lemke's method ends on a secondary ray; Newton's method with the
# floating blocks held by springs (the proximal iteration,
# doc/state_iteration.md) must conclude. Asserted: exit code 0, and the
# equilibrium the answer must have whatever iteration reached it: the treads
# (interfaces 1 to 8) carry the weight of the column, 25e3 x 16.5 m^2 =
# (0, 412500) N/m, and the two stable top blocks (interfaces 7 and 8) their
# own, (0, 43750) and (0, 18750). Relative tolerance 1e-6: the screen prints
# resultants to 7 significant digits. Iteration counts are not compared:
# with two BLAS threads Newton's stalled first try takes other steps (the
# same answer).
# Usage: below_limit.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
status=0
for case in "0.9807 0.5" "0.985 0.497796179"; do
  set -- $case
  cat > column_$1.prm <<PRM
include $source_dir/parameters/toppling_column.prm
set Test mode = true
subsection Contact
  set Friction coefficient = $2
end
subsection Output
  set Directory = $work/results_$1
  set Write VTU = false
end
PRM
  "$mbfem" column_$1.prm > column_$1.log 2>&1
  code=$?
  grep "increment 1/1" column_$1.log | cut -c1-110
  if [ $code -ne 0 ]; then
    echo "FAIL: $1 of the limit ended with exit code $code"
    tail -5 column_$1.log
    status=1
    continue
  fi
  awk -v lambda="$1" '
    /interface [0-9]+: resultant force on side b/ {
      k = $2 + 0
      gsub(/[(),]/, " ")
      fx[k] = $(NF - 1) + 0; fy[k] = $NF + 0
    }
    function check(what, x, y, ex, ey) {
      if ((x - ex)^2 + (y - ey)^2 > (1e-6 * 412500)^2) {
        printf "FAIL: %s of the limit: %s (%.7g, %.7g), expected (%g, %g)\n", lambda, what, x, y, ex, ey
        bad = 1
      } else
        printf "%s of the limit: %s (%.7g, %.7g) as expected\n", lambda, what, x, y
    }
    END {
      for (k = 1; k <= 8; ++k) { sx += fx[k]; sy += fy[k] }
      check("treads carry", sx, sy, 0, 412500)
      check("interface 7 carries", fx[7], fy[7], 0, 43750)
      check("interface 8 carries", fx[8], fy[8], 0, 18750)
      exit bad
    }' column_$1.log || status=1
done
exit $status
