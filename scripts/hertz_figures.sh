#!/usr/bin/env bash
# Runs the Hertz/Mindlin example (both variants, p = 1, 2, 3, at the paper's
# resolution and twice it) and plots p(x), q(x) against the closed forms
# into doc/figures/. Needs the build (scripts/setup.sh) and Debian's
# python3-matplotlib. About 20 s.
set -euo pipefail
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mbfem=${MBFEM_BUILD_DIR:-$source_dir/build}/mbfem
work=$(mktemp -d)
cd "$work"

for variant in hertz_mindlin hertz_mindlin_symmetric; do
  args=()
  for case in "1 36 paper" "2 18 paper" "3 12 paper" "1 72 fine" "2 36 fine" "3 24 fine"; do
    set -- $case
    name=${variant}_p$1_$3
    cat > $name.prm <<PRM
include $source_dir/parameters/$variant.prm
subsection Mesh
  set Mesh file = $source_dir/meshes/hertz_$2.msh
end
subsection Finite element
  set Polynomial degree = $1
end
subsection Output
  set Directory = $name
  set Write VTU = false
end
PRM
    "$mbfem" $name.prm > $name.log
    echo "$name: $(grep 'relative L2' $name.log | sed 's/.*traction: //')"
    args+=("$name/$(grep -o 'Base name = .*' $source_dir/parameters/$variant.prm | cut -d' ' -f4)-pairs-0020.csv:p = $1, $(( $1 * $2 + 1 )) pairs")
  done
  /usr/bin/python3 "$source_dir/scripts/plot_hertz.py" \
    "$source_dir/doc/figures/$variant.png" \
    "$variant.prm at t = 2 (P = 10, Q = 0.936 N/mm)" "${args[@]}"
done
rm -rf "$work"
echo "figures in doc/figures/hertz_mindlin.png, hertz_mindlin_symmetric.png"
