#!/bin/bash
# Lists the functions in source/ longer than a limit (default 80 lines),
# longest first: "lines file:line name". Issue 11 asks for functions under
# about 80 lines, except where a comment says why. Lengths are counted by
# universal-ctags from the line of the function's name to its closing
# brace (lambdas are counted inside their function, not on their own).
# Usage: bash scripts/long_functions.sh [LIMIT]
set -euo pipefail
limit=${1:-80}
cd "$(dirname "$0")/.."
command -v ctags >/dev/null ||
  { echo "long_functions.sh: needs universal-ctags (apt install universal-ctags)" >&2; exit 1; }
find source -name '*.cc' | sort |
  xargs ctags --c++-kinds=f --fields=+ne --sort=no -f - |
  awk -F'\t' -v limit="$limit" '
    $1 !~ /^__anon/ {
      line = ""; end = ""; scope = ""
      for (i = 4; i <= NF; ++i) {
        if ($i ~ /^line:/) line = substr($i, 6)
        else if ($i ~ /^end:/) end = substr($i, 5)
        else if ($i ~ /^(class|struct|namespace):/) { scope = $i; sub(/^[a-z]+:/, "", scope) }
      }
      if (line == "" || end == "") next
      n = end - line + 1
      if (n > limit) {
        sub(/^mbfem::/, "", scope)
        printf "%5d %s:%s %s%s\n", n, $2, line, (scope == "" || scope == "mbfem" ? "" : scope "::"), $1
      }
    }' |
  sort -rn
