#!/usr/bin/env bash
# README command 2 (and what CI runs): set up if needed, check the code
# format, run the whole test suite with ctest on two cores (Release), then
# build Debug and run every test not labelled slow in it.
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MBFEM_BUILD_DIR:-$source_dir/build}

start=$(date +%s)
bash "$source_dir/scripts/setup.sh"
bash "$source_dir/scripts/indent.sh" --check

echo "mbfem tests: building the test programs and running ctest"
cd "$build_dir"
ctest -j2 --output-on-failure
echo "mbfem tests: Release pass finished after $(( $(date +%s) - start )) s"

# The Debug pass: deal.II's Asserts (index bounds, sizes, states) on, every
# test not labelled slow in tests/CMakeLists.txt. MBFEM_DEBUG_TESTS=0 skips
# it; MBFEM_DEBUG_TESTS=all runs the slow tests too.
debug_tests=${MBFEM_DEBUG_TESTS:-1}
if [ "$debug_tests" != 0 ]; then
  debug_dir=${MBFEM_DEBUG_BUILD_DIR:-$source_dir/build-debug}
  echo "mbfem tests: Debug build in $debug_dir (2 jobs)"
  if [ ! -f "$debug_dir/CMakeCache.txt" ]; then
    cmake -S "$source_dir" -B "$debug_dir" -DCMAKE_BUILD_TYPE=Debug > /dev/null
  fi
  cmake --build "$debug_dir" -- -j2 | grep -E "error|warning" || true
  test -x "$debug_dir/mbfem" || { echo "mbfem tests: Debug build failed" >&2; exit 1; }
  cd "$debug_dir"
  if [ "$debug_tests" = all ]; then
    ctest -j2 --output-on-failure
  else
    ctest -j2 -LE slow --output-on-failure
  fi
fi
echo "mbfem tests: finished in $(( $(date +%s) - start )) s"
