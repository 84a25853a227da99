#!/usr/bin/env bash
# Runs mbfem on a bad input and checks that it fails as a user should see:
#   - a non-zero exit code, and the one of a '# expect-exit: N' line if
#     the input has one (2: no equilibrium, certified by the statics
#     certificate; 3: the iteration failed although admissible contact
#     forces exist; 1: anything else),
#   - every '# expect: REGEX' line of the input matched by stderr,
#   - every '# expect-file: PATH' present afterwards (results of increments
#     that converged stay on disk),
#   - no partially written file (*.part) left behind.
# Usage: expect_failure.sh MBFEM INPUT.prm WORKDIR
set -u
mbfem=$1
input=$2
work=$3

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
"$mbfem" "$input" > stdout 2> stderr
status=$?
cat stdout stderr

failed=0
if [ $status -eq 0 ]; then
  echo "FAIL: mbfem exited with 0 on a bad input"
  failed=1
fi
expected_status=$(sed -n 's/^# expect-exit: *//p' "$input" | head -n 1)
if [ -n "$expected_status" ] && [ "$status" -ne "$expected_status" ]; then
  echo "FAIL: mbfem exited with $status, expected $expected_status"
  failed=1
fi
n_expect=0
while IFS= read -r pattern; do
  n_expect=$((n_expect + 1))
  if ! grep -E -q -- "$pattern" stderr; then
    echo "FAIL: the error message does not match: $pattern"
    failed=1
  fi
done < <(sed -n 's/^# expect: //p' "$input")
if [ $n_expect -eq 0 ]; then
  echo "FAIL: $input has no '# expect:' line"
  failed=1
fi
while IFS= read -r file; do
  if [ ! -s "$file" ]; then
    echo "FAIL: expected output file $file is missing"
    failed=1
  fi
done < <(sed -n 's/^# expect-file: //p' "$input")
if [ -n "$(find . -name '*.part')" ]; then
  echo "FAIL: partially written files were left behind"
  failed=1
fi
[ $failed -eq 0 ] && echo "PASS: exit code $status, message as expected"
exit $failed
