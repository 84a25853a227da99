#!/usr/bin/env bash
# Sets mbfem up on Debian 12: installs the Debian packages it needs (only
# those missing), then configures (Release) and builds with two jobs.
# Incremental: a second call only rebuilds what changed.
#
#   bash scripts/setup.sh            build in ./build
#   MBFEM_BUILD_DIR=/tmp/b bash scripts/setup.sh
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${MBFEM_BUILD_DIR:-$source_dir/build}

# deal.II 9.4 with Trilinos, p4est, MPI, gmsh, UMFPACK; MUMPS's C API
# (block flexibilities); OpenBLAS (threaded) for dense LAPACK and MUMPS
# through Debian's alternatives; gmsh for meshes;
# numdiff and perl for deal.II's test macros; clang-format for the style
# check; COIN-OR Clp for the statics certificate's linear program; gmsh's
# C API for rock masses; OpenTURNS for Mode = reliability (distributions,
# copulas, samples, FORM); matplotlib for the default example's
# figure; SciPy and CVXOPT for the scripts that check written contact
# problems; Open MPI's mpirun for runs and tests on several ranks; the
# compiler and build tools.
packages="libdeal.ii-dev libmetis-dev libmumps-dev openmpi-bin libopenblas0-pthread gmsh numdiff perl cmake make g++ clang-format coinor-libclp-dev libgmsh-dev libopenturns-dev python3-matplotlib python3-scipy python3-cvxopt"

missing=""
for package in $packages; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null |
       grep -q "install ok installed"; then
    missing="$missing $package"
  fi
done

if [ -n "$missing" ]; then
  echo "mbfem setup: installing Debian packages:$missing"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq $missing \
    > "${TMPDIR:-/tmp}/mbfem-apt.log" 2>&1 || {
      echo "mbfem setup: apt-get failed; its log:" >&2
      tail -n 30 "${TMPDIR:-/tmp}/mbfem-apt.log" >&2
      exit 1
    }
  echo "mbfem setup: packages installed"
else
  echo "mbfem setup: all Debian packages present"
fi

if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  echo "mbfem setup: configuring a Release build in $build_dir"
  cmake -S "$source_dir" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
echo "mbfem setup: building (2 jobs)"
cmake --build "$build_dir" -- -j2 | grep -E "error|warning|Built target" || true
test -x "$build_dir/mbfem" || { echo "mbfem setup: build failed" >&2; exit 1; }
echo "mbfem setup: done, the program is $build_dir/mbfem"
