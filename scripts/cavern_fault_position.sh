#!/bin/bash
# Where the fault enters the cavern's left wall decides which rock wedge
# moves. This runs parameters/cavern_fault.prm (elastic) and
# parameters/cavern_fault_plastic.prm (Mohr-Coulomb, psi = 12.5) on meshes
# of meshes/cavern_fault.geo with the fault entering the left wall 5, 10
# (the default) and 15 m above the floor (yw = -25, -20, -15), and prints
# the left wall's slip and the largest slip of each run.
#
#   bash scripts/cavern_fault_position.sh [BUILD_DIR]   (about 3.5 minutes)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
mbfem=${1:-$root/build}/mbfem
out=$root/build/cavern-position
mkdir -p "$out"
for yw in -25 -20 -15; do
  gmsh -2 -format msh22 -setnumber yw "$yw" "$root/meshes/cavern_fault.geo" \
    -o "$out/fault_yw$yw.msh" > "$out/gmsh_yw$yw.log" 2>&1 || { echo "gmsh failed"; exit 1; }
  for base in cavern_fault cavern_fault_plastic; do
    name=${base}_yw$yw
    cat > "$out/$name.prm" <<PRM
include $root/parameters/$base.prm
subsection Mesh
  set Mesh file = $out/fault_yw$yw.msh
end
subsection Output
  set Directory = $out
  set Base name = $name
  set Write VTU = false
end
PRM
    /usr/bin/time -f "%e" -o "$out/$name.time" "$mbfem" "$out/$name.prm" > "$out/$name.log" 2>&1
    status=$?
    last=$(ls "$out/$name"-pairs-*.csv | sort | tail -1)
    /usr/bin/python3 - "$root/scripts" "$last" "$yw" "$base" "$status" "$(tail -1 "$out/$name.time")" <<'PY'
import csv, sys
sys.path.insert(0, sys.argv[1])
from cavern_slip_curves import left_wall_slip
path, yw, base, status, seconds = sys.argv[2:]
t, wall_slip, _ = left_wall_slip(path)
with open(path) as f:
    f.readline()
    largest = max(csv.DictReader(f), key=lambda r: abs(float(r["slip_1"])))
print("fault %4.0f m above the floor, %-9s: t = %.2f%s, left-wall slip %5.1f mm, "
      "largest slip %5.1f mm at x = %5.1f m, %s s"
      % (float(yw) + 30, "elastic" if base == "cavern_fault" else "plastic", t,
         "" if status == "0" else " (failed after)", wall_slip,
         1e3 * abs(float(largest["slip_1"])), float(largest["x"]), seconds))
PY
  done
done
