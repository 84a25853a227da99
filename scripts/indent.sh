#!/usr/bin/env bash
# Formats the C++ sources with the project's .clang-format (deal.II style),
# or with --check reports the files that are not formatted and fails.
set -euo pipefail

source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$source_dir"
files=$(git ls-files --cached --others --exclude-standard '*.cc' '*.h' 2>/dev/null || find source include tests -name '*.cc' -o -name '*.h')

if [ "${1:-}" = "--check" ]; then
  bad=""
  for f in $files; do
    clang-format --dry-run -Werror "$f" > /dev/null 2>&1 || bad="$bad $f"
  done
  if [ -n "$bad" ]; then
    echo "Not formatted by .clang-format (run bash scripts/indent.sh):$bad" >&2
    exit 1
  fi
  echo "mbfem format: all files formatted"
else
  clang-format -i $files
fi
