#!/usr/bin/env bash
# README command 2 (and what CI runs): set up if needed, check the code
# format, then run the whole test suite with ctest on two cores.
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MBFEM_BUILD_DIR:-$source_dir/build}

start=$(date +%s)
bash "$source_dir/scripts/setup.sh"
bash "$source_dir/scripts/indent.sh" --check

echo "mbfem tests: building the test programs and running ctest"
cd "$build_dir"
ctest -j2 --output-on-failure
echo "mbfem tests: finished in $(( $(date +%s) - start )) s"
