#!/usr/bin/env bash
# Strength reduction of Hoek and Bray's wedge (parameters/wedge_3d.prm,
# mu = 0.7002075382 so that the closed-form factor of safety is 1.3249).
# The last converged trial is a slide just below the limit: every pair
# slips, and there the slip, |u|, the pressure's range and each interface's
# share of the weight depend on how close to the limit the bisection's last
# factor lies (1.324225 or 1.324226 with two BLAS kernels: max slip moved by
# 7e-4 relative, the resultants' x by 2e-6). So this test asserts only what
# does not depend on that, where the stored screen output compared all of
# it:
#  - exit code 0, and the closed form inside the search's bracket;
#  - F within 1e-3 relative of 1.3249 (implied by the bracket, whose
#    relative width is the search's tolerance, 'Strength
#    reduction/Tolerance' = 1e-3; checked to say the printed F);
#  - every pair slips at the last factor: stick/slip/open 0/122/0 (so at
#    every fixed F from 1.30 to 1.3247 in a review's runs; 18/104/0 at
#    1.2);
#  - Coulomb holds on both interfaces;
#  - the two interfaces carry the wedge's weight, 25e3 x volume of the
#    tetrahedron O A B C of meshes/wedge_3d.geo (4656.4 m^3; trilinear
#    hexahedra integrate the volume exactly), to 1e-6 relative (116 N):
#    the screen prints each resultant to 7 significant digits, 10 N, so
#    the printed sum is within 10 N of the computed one.
# Usage: unique_at_slide.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
sed "s#@SOURCE_DIR@#$source_dir/tests#" "$source_dir/tests/srm_wedge_3d.prm.in" \
  > wedge.prm
cat >> wedge.prm <<PRM
subsection Output
  set Directory = $work/results
end
PRM
"$mbfem" wedge.prm > wedge.log 2>&1
code=$?
if [ $code -ne 0 ]; then
  echo "FAIL: exit code $code"
  tail -5 wedge.log
  exit 1
fi
awk '
  function fail(what) { print "FAIL: " what; bad = 1 }
  /^factor of safety = / { F = $5 + 0; found_F = 1 }
  /the bracket holds it: yes/ { bracket = 1 }
  /increment 1\/1, t = 1:/ {
    match($0, /stick\/slip\/open [0-9]+\/[0-9]+\/[0-9]+/)
    states = substr($0, RSTART + 16, RLENGTH - 16)
  }
  /Coulomb: slipping pairs on the cone yes, stuck pairs inside it yes/ { ++coulomb }
  /interface [0-9]+: resultant force on side b/ {
    gsub(/[(),]/, " ")
    fx += $(NF - 2); fy += $(NF - 1); fz += $NF; ++n_resultants
  }
  END {
    # The tetrahedron O A B C of meshes/wedge_3d.geo.
    ax = -26.4285; ay = 7.2794; az = 20
    bx = 26.4285;  by = 7.2794; bz = 20
    cx = 0;        cy = 33.7079; cz = 20
    volume = (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6
    weight = 25e3 * (volume < 0 ? -volume : volume)
    if (!found_F) fail("no factor of safety")
    else if ((F - 1.3249)^2 > (1e-3 * 1.3249)^2) fail(sprintf("F = %.6f, not within 1e-3 of 1.3249", F))
    else printf "F = %.4f, within 1e-3 of the closed form 1.3249\n", F
    if (!bracket) fail("the bracket does not hold the closed form")
    else print "the bracket holds the closed form"
    if (states != "0/122/0") fail("states at the last factor " states ", expected 0/122/0")
    else print "every pair slips at the last factor: 0/122/0"
    if (coulomb != 2) fail("Coulomb not confirmed on both interfaces")
    else print "Coulomb holds on both interfaces"
    if (n_resultants != 2 || fx^2 + fy^2 + (fz - weight)^2 > (1e-6 * weight)^2)
      fail(sprintf("the interfaces carry (%.7g, %.7g, %.7g), the weight is %.7g", fx, fy, fz, weight))
    else printf "the interfaces carry the weight %.6g to 1e-6\n", weight
    exit bad
  }' wedge.log
