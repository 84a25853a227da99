#!/usr/bin/env bash
# Issue 66: blocks held only together. Lame's quarter ring (parameters/
# order_study_lame.prm) as one block, cut into two blocks at 45 degrees
# and into four at 22.5, 45 and 67.5 degrees, bonded by interfaces of
# cohesion and tensile strength 1e6 (pressure 1). No block of the cut
# rings is held on its own (the rollers x = 0 and y = 0 lie on different
# blocks; the middle ones have none): the group is. The bonded model is the
# same discrete problem as the uncut ring, so the relative L2 errors of the
# displacement and the stress must equal the single block's to every
# printed digit, at p = 1 and 2 on refinement levels 1 and 2. Then the
# two-block ring with one roller removed must be refused, naming the free
# motion (translation y).
# Usage: compare.sh MBFEM SOURCE_DIR WORK_DIR
set -u
mbfem=$1
source_dir=$2
work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

cut_2="set Block id function = (y > x)"
cut_4="set Block id function = (y > 0.41421356237*x) + (y > x) + (y > 2.41421356237*x)"
interfaces_2="set Interfaces = blocks 0:1"
interfaces_4="set Interfaces = blocks 0:1; blocks 1:2; blocks 2:3"

write() { # name, blocks, degree, level, supports
  local cut="" interfaces=""
  [ "$2" = 2 ] && cut=$cut_2 && interfaces=$interfaces_2
  [ "$2" = 4 ] && cut=$cut_4 && interfaces=$interfaces_4
  cat > "$1.prm" <<PRM
include $source_dir/parameters/order_study_lame.prm
set Mode = simulation
subsection Mesh
  set Generator arguments       = 0,0 : 1 : 2 : 4 : true
  set Initial global refinement = $4
  $cut
end
subsection Finite element
  set Polynomial degree = $3
end
subsection Boundary conditions
  set Prescribed displacement boundary ids = $5
end
subsection Contact
  $interfaces
  set Cohesion         = 1e6
  set Tensile strength = 1e6
end
subsection Output
  set Directory = $work/$1
  set Write VTU = false
end
PRM
}

failed=0
for p in 1 2; do
  for level in 1 2; do
    for blocks in 1 2 4; do
      name=ring$blocks-p$p-level$level
      write $name $blocks $p $level "2: x, 3: y"
      if ! "$mbfem" $name.prm > $name.out 2>&1; then
        echo "FAILED: $name did not run:"; tail -n 5 $name.out; failed=1
        continue
      fi
      errors=$(grep "L2 errors against the exact solution" $name.out)
      [ $blocks = 1 ] && reference=$errors
      echo "$blocks block(s), p = $p, level $level: ${errors#*: }"
      if [ -z "$errors" ] || [ "$errors" != "$reference" ]; then
        echo "FAILED: $name's errors differ from the single block's"
        failed=1
      fi
    done
  done
done

# One roller fewer: the group of two blocks can move along y.
write free 2 1 1 "2: x"
"$mbfem" free.prm > free.out 2>&1
code=$?
if [ $code = 0 ] ||
   ! grep -q "as one body the group keeps 1 rigid motion(s) free, \[translation y\]" free.out; then
  echo "FAILED: the ring with one roller removed was not refused as expected (exit $code):"
  tail -n 5 free.out
  failed=1
else
  echo "one roller removed: refused (exit $code), naming [translation y]"
fi
exit $failed
