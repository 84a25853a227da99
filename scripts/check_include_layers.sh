#!/bin/bash
# The include graph of mbfem runs one way (doc/architecture.md, "Layers"):
# a file of include/mbfem/<area>/ or source/<area>/ may include headers of
# its own area and of the areas below it, never of one above.
#
#   scripts/check_include_layers.sh [ROOT]      (ROOT: the source tree)
#   scripts/check_include_layers.sh --planted   (the check must fail on a
#                                                copy with one upward include)
#
# Prints every include that runs up, with file and line, and exits 1 if
# there is one. ctest runs both forms (style/include_layers*).

# Lowest first. An area may include itself and anything to its left.
LAYERS=(base linear_algebra mesh material block interface contact output
        analysis)

rank_of() {
  local i
  for i in "${!LAYERS[@]}"; do
    [[ ${LAYERS[$i]} == "$1" ]] && { echo "$i"; return; }
  done
  echo -1
}

check() {
  local root=$1 status=0 file area included line
  for file in "$root"/include/mbfem/*/*.h "$root"/source/*/*.cc; do
    area=$(basename "$(dirname "$file")")
    local own
    own=$(rank_of "$area")
    if ((own < 0)); then
      echo "$file: area '$area' is not in the layers of $0"
      status=1
      continue
    fi
    while IFS=: read -r line included; do
      local theirs
      theirs=$(rank_of "$included")
      if ((theirs < 0)); then
        echo "$file:$line: includes area '$included', which has no layer"
        status=1
      elif ((theirs > own)); then
        echo "$file:$line: $area includes $included, a layer above it"
        status=1
      fi
    done < <(grep -n -o '^#include <mbfem/[a-z_]*/' "$file" |
             sed 's|#include <mbfem/||; s|/$||')
  done
  return $status
}

if [[ $1 == --planted ]]; then
  # A copy of the tree with one upward include planted: the check must
  # find it, or it proves nothing.
  source_root=$(cd "$(dirname "$0")/.." && pwd)
  copy=$(mktemp -d)
  trap 'rm -rf "$copy"' EXIT
  cp -r "$source_root/include" "$source_root/source" "$copy/"
  sed -i '1i #include <mbfem/analysis/parameters.h>' \
    "$copy/include/mbfem/base/exceptions.h"
  if output=$(check "$copy"); then
    echo "FAILED: an upward include planted in base/exceptions.h was not found"
    exit 1
  fi
  echo "$output"
  if ! grep -q "exceptions.h:1: base includes analysis" <<<"$output"; then
    echo "FAILED: the planted include was not the one reported"
    exit 1
  fi
  echo "the planted upward include is found"
  exit 0
fi

root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
if check "$root"; then
  echo "includes run one way: ${LAYERS[*]}"
else
  exit 1
fi
