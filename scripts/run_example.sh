#!/usr/bin/env bash
# README command 1: set up if needed, then run the default example (or the
# parameter file given) in ./results: a summary on screen, VTU/PVD on disk.
#
#   bash scripts/run_example.sh [FILE.prm]
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MBFEM_BUILD_DIR:-$source_dir/build}
input=${1:-$source_dir/parameters/timoshenko_cantilever.prm}

bash "$source_dir/scripts/setup.sh"
echo
"$build_dir/mbfem" "$input"
echo
echo "Open results/*.pvd in ParaView to see the displacement and stresses."
