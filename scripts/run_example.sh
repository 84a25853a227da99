#!/usr/bin/env bash
# README command 1: set up if needed, then run the default example (or the
# parameter file given) in ./results: a summary on screen, VTU/PVD on disk.
#
# The default is the paper's first example, two elastic half-disks in
# Hertz/Mindlin contact (parameters/hertz_mindlin_symmetric.prm): after the
# run its contact tractions are compared with the closed forms, and p(x),
# q(x) are drawn against Hertz and Mindlin in results/hertz_symmetric.png.
#
#   bash scripts/run_example.sh [FILE.prm]
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MBFEM_BUILD_DIR:-$source_dir/build}
default=$source_dir/parameters/hertz_mindlin_symmetric.prm
input=${1:-$default}

bash "$source_dir/scripts/setup.sh"
echo
"$build_dir/mbfem" "$input"
echo
if [ "$input" = "$default" ]; then
  /usr/bin/python3 "$source_dir/scripts/plot_hertz.py" \
    results/hertz_symmetric.png \
    "hertz_mindlin_symmetric.prm at t = 2 (P = 10, Q = 0.936 N/mm)" \
    "results/hertz_symmetric-pairs-0020.csv:mbfem, FE_Q(1), 37 pairs"
  echo
fi
echo "Open results/*.pvd in ParaView to see the displacements and stresses"
echo "(and results/*-pairs.pvd for the contact pairs)."
