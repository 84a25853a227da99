#!/usr/bin/env bash
# Benchmarks of the multi-body method against the monolithic
# Lagrange-multiplier solve of the same mesh (issue 12): runs each model
# under /usr/bin/time -v, prints a table and writes doc/benchmarks.md.
# Figures, not tests: nothing here is timed in ctest.
#
#   bash benchmarks/run.sh                      all models below
#   bash benchmarks/run.sh stacked_1377 hertz   some of them
#   MBFEM=/path/to/mbfem MBFEM_BENCH_DIR=/tmp/b bash benchmarks/run.sh
#
# The model variants are generated as .prm files from
# parameters/stacked_cantilevers.prm (stacked_N: N pairs; stacked_6697, the
# largest that fits in 24 GB here, takes some 18 GB and 20 minutes),
# parameters/hertz_mindlin.prm, parameters/wall_16x16_2d.prm (wall_N: N
# blocks), parameters/cube_5x5x5.prm (gravity alone) and
# parameters/rock_mass_1000.prm (1000 blocks from three joint sets; its
# bonded run reads the mesh the first run built). Each is also run
# as one bonded block with one increment and no contact, the "one linear
# elastic solve of the same mesh" the table divides by. Do not edit this
# file while it runs (bash reads it as it goes).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mbfem=${MBFEM:-$root/build/mbfem}
work=${MBFEM_BENCH_DIR:-$root/build/benchmarks}
mkdir -p "$work"

# name: base file | mesh arguments (stacked) or mesh file (Hertz) |
#       degree | increments | formulation
declare -A models=(
  [hertz]="hertz_mindlin|hertz_36.msh|1|20|both"
  [hertz_fine]="hertz_mindlin|hertz_72.msh|1|20|both"
  [stacked_105]="stacked_cantilevers|10,2,2|2|10|both"
  [stacked_369]="stacked_cantilevers|40,8,8|1|10|both"
  [stacked_1377]="stacked_cantilevers|80,16,8|1|10|both"
  [stacked_1377_100]="stacked_cantilevers|80,16,8|1|100|both"
  [stacked_5313]="stacked_cantilevers|160,32,8|1|10|condensed"
  [stacked_6697]="stacked_cantilevers|180,36,8|1|10|condensed"
  [wall_16]="wall_16x16_2d|4|2|1|both"
  [wall_64]="wall_16x16_2d|8|2|1|both"
  [wall_256]="wall_16x16_2d|16|2|1|both"
  [cube_125]="cube_5x5x5|5|2|1|condensed"
  [rock_mass_1000]="rock_mass_1000|10|2|1|condensed"
)
order="hertz hertz_fine stacked_105 stacked_369 stacked_1377 stacked_1377_100 stacked_5313 stacked_6697 wall_16 wall_64 wall_256 cube_125 rock_mass_1000"
selected=${*:-$order}

make_prm() { # name bonded(0/1) -> writes $work/name[-elastic].prm
  local name=$1 bonded=$2
  IFS='|' read -r base mesh degree increments formulation <<< "${models[$name]}"
  local out=$work/$name$([ "$bonded" = 1 ] && echo -elastic).prm
  sed -e "s|Generator arguments = 10,2,2 : 0,0,0|Generator arguments = $mesh : 0,0,0|" \
      -e "s|Mesh file *= ../meshes/hertz_36.msh|Mesh file = $root/meshes/$mesh|" \
      -e "s|Polynomial degree = [0-9]|Polynomial degree = $degree|" \
      -e "s|Number of increments = [0-9]*|Number of increments = $increments|" \
      -e "s|Formulation *= .*|Formulation = $formulation|" \
      -e "s|Directory = .*|Directory = $work/results-$name|" \
      "$root/parameters/$base.prm" > "$out"
  if [[ $name == wall* ]]; then
    # An n x n wall of 1 x 0.5 blocks on a base 0.5 thick (the 16 x 16
    # wall of parameters/ with n blocks a course and n courses).
    local n=$mesh h
    h=$(awk "BEGIN { print ($n + 1) / 2 }")
    sed -i -e "s|Generator arguments = .*|Generator arguments = $((2 * n)),$((n + 1)) : 0,0 : $n,$h : true|" \
           -e "s|Block id function *= .*|Block id function = (y > 0.5) * (1 + floor(x) + $n*floor(2*y - 1))|" \
           "$out"
  fi
  if [[ $name != stacked* ]]; then
    printf 'subsection Contact\n  set Formulation = %s\nend\n' "$formulation" >> "$out"
  fi
  if [[ $name == wall* || $name == cube* ]]; then
    # The cube: gravity alone (its push, at t = 2, is left out: End time 1).
    printf 'subsection Load history\n  set End time = 1\n  set Number of increments = %s\nend\n' "$increments" >> "$out"
    printf 'subsection Output\n  set Directory = %s\n  set Write VTU = false\nend\n' "$work/results-$name" >> "$out"
  fi
  if [[ $name == stacked* || ( $name == rock_mass* && $bonded = 1 ) ]]; then
    # KLU has no nested dissection: 3D blocks factorise with MUMPS (the
    # rock mass's blocks, one cell each, with KLU; its bonded mesh, 27783
    # DoFs, took 58 s with KLU).
    printf 'subsection Linear solver\n  set Direct solver = Amesos_Mumps\nend\n' >> "$out"
  fi
  if [[ $name == rock_mass* && "$bonded" = 1 ]]; then
    # The mesh the rock mass run built (gmsh), as one block.
    printf 'subsection Mesh\n  set Source = gmsh\n  set Mesh file = %s\n  set Block id function = 0\nend\n' \
      "$work/results-$name/$base-rock-mass.msh" >> "$out"
    printf 'subsection Contact\n  set Joint sets =\nend\n' >> "$out"
  fi
  if [ "$bonded" = 1 ]; then
    # One block (the stacked beams bonded), one increment, no contact.
    sed -i -e "s|Block id function *= .*|Block id function = 0|" \
           -e "s|Number of increments = [0-9]*|Number of increments = 1|" \
           -e "s|^ *set Interfaces .*|  set Interfaces =|" \
           -e "s|Write VTU *= .*|Write VTU = false|" "$out"
  fi
  echo "$out"
}

for name in $selected; do
  [ -n "${models[$name]:-}" ] || { echo "unknown model $name" >&2; exit 1; }
  for bonded in 0 1; do
    [ "$bonded" = 1 ] && [[ $name == hertz* ]] && continue # two bodies
    [ "$bonded" = 1 ] && [[ $name == *_100 ]] && continue  # same mesh
    prm=$(make_prm "$name" "$bonded")
    log=${prm%.prm}.log
    echo "benchmarks: $(basename "$prm")" >&2
    /usr/bin/time -v "$mbfem" "$prm" > "$log" 2>&1 || {
      echo "benchmarks: $prm failed, see $log" >&2; }
  done
done

python3 "$root/benchmarks/table.py" "$work" $selected \
  --command "bash benchmarks/run.sh $*" > "$root/doc/benchmarks.md"
cat "$root/doc/benchmarks.md"
