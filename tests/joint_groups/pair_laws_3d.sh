#!/usr/bin/env bash
# Issue 61, part 3: joint laws by gmsh physical group, in 3D, with one
# interface over two groups (meshes/joint_groups_3d.geo): a block on a base
# whose joint is the surfaces "rough" (x < 1, friction 0.6) and "smooth"
# (x > 1, friction 0.2). A horizontal body force k W, k = 0.3, between the
# two frictions: each pair must keep to its own group's law, so every pair
# at x > 1 has |T| <= 0.2 N and some slip at 0.2 (the smooth half cannot
# carry 0.3), while pairs at x < 1 carry more than 0.2 N (up to 0.6 N); the
# interface as a whole carries (-k W, 0, W) = (-30000, 0, 100000). A node
# on x = 1 lies on faces of both groups in equal shares and takes the
# group of the lower physical tag ("rough"). The face x = 1 inside the top
# block is in a group ("inside") that is no joint, and the screen says so.
# Usage: pair_laws_3d.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

cat > run.prm <<PRM
set Dimension = 3
subsection Mesh
  set Source    = gmsh
  set Mesh file = $source_dir/meshes/joint_groups_3d.msh
end
subsection Finite element
  set Polynomial degree = 2
end
subsection Material
  set Young's modulus = 1e9
  set Poisson's ratio = 0.25
  set Unit weight     = 25e3
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = 1: xyz
  subsection Body force
    set Variable names      = x,y,z,t
    set Function constants  = k=0.3
    set Function expression = k * 25e3 * t; 0; 0
  end
end
subsection Contact
  set Interfaces           = all
  set Friction coefficient = 0.9
  set Joint sets           = rough: group rough, friction 0.6; smooth: group smooth, friction 0.2
end
subsection Load history
  set Number of increments = 2
end
subsection Output
  set Base name = groups
  set Write VTU = false
end
PRM
"$mbfem" run.prm > screen.txt 2>&1
status=$?
cat screen.txt
[ $status -eq 0 ] || { echo "FAIL: mbfem exited with $status"; exit 1; }
fail=0
for line in "joint group 'rough' of the mesh: joint set rough, area 2" \
            "joint group 'smooth' of the mesh: joint set smooth, area 2" \
            "joint group 'inside' of the mesh: no joint set names it" \
            "area 2, of which 0 between two blocks" \
            "1 interface(s) with pairs in more than one joint set" \
            "resultant force on side b (-3.000000e+04, 0.000000e+00, 1.000000e+05)"; do
  grep -qF "$line" screen.txt || { echo "FAIL: the screen lacks: $line"; fail=1; }
done
python3 - results/groups-pairs-0002.csv <<'PY' || fail=1
import csv, math, sys
lines = [l for l in open(sys.argv[1]) if not l.startswith('#')]
rows = list(csv.DictReader(lines))
worst_smooth, slipping_smooth, most_rough = 0., 0, 0.
for r in rows:
    x = float(r['x'])
    n = float(r['normal_force'])
    t = math.hypot(float(r['tangential_force_1']), float(r['tangential_force_2']))
    if x > 1 + 1e-9:
        worst_smooth = max(worst_smooth, t / n)
        slipping_smooth += (r['state'] == 'slip')
    elif x < 1 - 1e-9:
        most_rough = max(most_rough, t / n)
print(f"{len(rows)} pairs; x > 1: largest |T|/N {worst_smooth:.12f}, "
      f"{slipping_smooth} slip; x < 1: largest |T|/N {most_rough:.6f}")
# |T| <= mu N holds to the iteration's round-off (1e-9 relative).
ok = (worst_smooth <= 0.2 * (1 + 1e-9) and slipping_smooth > 0 and
      0.2 * 1.1 < most_rough <= 0.6 * (1 + 1e-9))
print("PASS" if ok else "FAIL: the pairs do not keep to their groups' laws")
sys.exit(0 if ok else 1)
PY
exit $fail
