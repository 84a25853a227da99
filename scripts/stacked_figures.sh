#!/usr/bin/env bash
# Runs the stacked cantilevers (the paper's example 2) condensed and, as a
# separate run, monolithic at the paper's 105 pairs (p = 1 and 2), and the
# refined 369-pair variant condensed, and plots the gap along the interface
# (the paper's Fig. 7) into doc/figures/stacked_cantilevers_gap.png. Needs
# the build (scripts/setup.sh) and Debian's python3-matplotlib. About 20 s.
set -euo pipefail
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mbfem=${MBFEM_BUILD_DIR:-$source_dir/build}/mbfem
work=$(mktemp -d)
cd "$work"

args=()
for case in "2 10,2,2 condensed paper line" "2 10,2,2 monolithic paper marker" \
            "1 20,4,4 condensed paper line" "2 20,4,4 condensed fine line"; do
  set -- $case
  name=stacked_p$1_$2_$3
  name=${name//,/x}
  cat > $name.prm <<PRM
include $source_dir/parameters/stacked_cantilevers.prm
subsection Mesh
  set Generator arguments = $2 : 0,0,0 : 10,2,2 : true
end
subsection Finite element
  set Polynomial degree = $1
end
subsection Contact
  set Formulation = $3
end
subsection Output
  set Directory = $name
  set Base name = stacked
  set Write VTU = false
end
PRM
  "$mbfem" $name.prm > $name.log
  echo "$name: $(grep 'time of' $name.log)"
  label="p = $1, $3"
  [ "$4" = fine ] && label="$label, refined"
  args+=("$name/stacked-pairs-0010.csv:$label:$5")
done
/usr/bin/python3 "$source_dir/scripts/plot_stacked_gap.py" \
  "$source_dir/doc/figures/stacked_cantilevers_gap.png" "${args[@]}"
rm -rf "$work"
echo "figure in doc/figures/stacked_cantilevers_gap.png"
