#!/usr/bin/env bash
# Runs a seeded campaign script of scripts/ in test mode (no times, no
# paths) and compares its output with the stored one by numdiff, with the
# tolerances of deal.II's run_test.sh (-a 1e-6 -r 1e-8), as the .prm tests
# are compared. A campaign asserts through its stored output (the counts
# of its summary), and also exits non-zero itself if any run differs from
# the verdict it expects.
# Usage: run_campaign.sh MBFEM SCRIPT.py STORED.output WORKDIR [ARGS...]
set -u
mbfem=$1
script=$2
stored=$3
work=$4
shift 4

rm -rf "$work" && mkdir -p "$work" || exit 1
python3 "$script" --mbfem "$mbfem" --work "$work/runs" --test "$@" \
  > "$work/output"
status=$?
cat "$work/output"
failed=0
if [ $status -ne 0 ]; then
  echo "FAIL: $script exited with $status"
  failed=1
fi
if ! numdiff -a 1e-6 -r 1e-8 -s ' \t\r\n=,:;<>[](){}^' "$stored" \
     "$work/output" > "$work/diff"; then
  echo "FAIL: the output differs from $stored:"
  head -n 40 "$work/diff"
  failed=1
fi
[ $failed -eq 0 ] && echo "PASS: the output equals $stored"
exit $failed
