#!/bin/bash
# The faulted cavern (parameters/cavern_fault*.prm) with elastic rock and
# with Mohr-Coulomb rock of dilatancy psi = 0, 12.5, 25 and 50 degrees
# (phi = 50), all solved with Newton's method; then the figure of the
# left wall's slip against the release, doc/figures/cavern_slip_curves.png.
# psi = 0 runs in steps of 0.25 % and ends with an error where it finds no
# equilibrium (about 87 %): that is one of the results.
#
#   bash scripts/cavern_dilatancy_study.sh [BUILD_DIR]   (about 8 minutes)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
mbfem=${1:-$root/build}/mbfem
out=$root/build/cavern-study
mkdir -p "$out"
run() { # name, extra parameter lines
  local name=$1; shift
  {
    echo "include $root/parameters/$base"
    echo "subsection Mesh"
    echo "  set Mesh file = $root/meshes/cavern_fault.msh"
    echo "end"
    printf '%s\n' "$@"
    echo "subsection Output"
    echo "  set Directory = $out"
    echo "  set Base name = $name"
    echo "  set Write VTU = false"
    echo "end"
  } > "$out/$name.prm"
  echo "== $name"
  /usr/bin/time -f "   %e s" "$mbfem" "$out/$name.prm" > "$out/$name.log" 2>&1 ||
    echo "   (ended with an error: $(grep -A1 'mbfem: error' "$out/$name.log" | tail -1))"
  tail -1 "$out/$name.log"
}
base=cavern_fault.prm
run elastic
base=cavern_fault_plastic.prm
run psi00 "subsection Plasticity" "set Dilatancy angle = 0" "end" \
  "subsection Load history" "set Number of increments = 360" \
  "set End time = 0.9" "set Maximum step halvings = 0" "end"
run psi12 # the parameter file's own psi = 12.5
run psi25 "subsection Plasticity" "set Dilatancy angle = 25" "end"
run psi50 "subsection Plasticity" "set Dilatancy angle = 50" "end"
/usr/bin/python3 "$root/scripts/cavern_slip_curves.py" \
  "$root/doc/figures/cavern_slip_curves.png" \
  "elastic rock=$out/elastic" "Mohr-Coulomb, psi = 0=$out/psi00" \
  "Mohr-Coulomb, psi = 12.5=$out/psi12" "Mohr-Coulomb, psi = 25=$out/psi25" \
  "Mohr-Coulomb, psi = 50 (associated)=$out/psi50"
