#!/usr/bin/env bash
# Runs mbfem on a bad input and checks that it fails as a user should see:
#   - a non-zero exit code, and the one of a '# expect-exit: N' line if
#     the input has one (2: no equilibrium, certified by the statics
#     certificate; 4: none along the mechanism of the statics limit
#     (limit equilibrium); 3: the iteration failed although admissible contact
#     forces exist; 1: anything else),
#   - every '# expect: REGEX' line of the input matched by stderr, no
#     '# expect-not: REGEX' line matched by it, and every
#     '# expect-stdout: REGEX' line matched by stdout,
#   - no deal.II exception dump (source location, stack trace) in stderr,
#   - every '# expect-file: PATH' present afterwards (results of increments
#     that converged stay on disk),
#   - no partially written file (*.part) left behind, and every file a PVD
#     index names present.
# '# input: FILE' runs mbfem on FILE (relative to the input's folder) instead,
# for inputs that cannot hold these comments (JSON).
# '# signal-on: REGEX SIGNAL' sends SIGNAL to mbfem once its stdout matches
# REGEX (which also shows that the screen output is not held in a buffer).
# '# setup: COMMAND' runs COMMAND (bash) in the working folder first, e.g. to
# put /dev/full where mbfem will write (a full disk without a mount).
# '# ranks: N' runs it as `mpirun -np N mbfem` and, unless it sends a signal,
# also on one process, and requires the same exit code, the same stderr and
# the same files (issue 30: rank 0 speaks for all ranks, and says what one
# process says); with '# ranks-compare: message' only the same exit code and
# stderr.
# Usage: expect_failure.sh MBFEM INPUT.prm WORKDIR
set -u
mbfem=$1
input=$2
work=$(realpath -m "$3")

run_input=$input
alternative=$(sed -n 's/^# input: //p' "$input")
[ -n "$alternative" ] && run_input=$(dirname "$input")/$alternative

ranks=$(sed -n 's/^# ranks: *//p' "$input" | head -n 1)
launch=()
compare=
if [ -n "$ranks" ]; then
  launch=(mpirun -q -np "$ranks") # -q: without mpirun's own notice of a failed rank
  # mpirun binds each rank to a core, where OpenBLAS runs one thread; the
  # one-process run compared with it must too (doc/parallel.md: the same
  # answer needs the same BLAS thread count). With two threads there, the
  # failed Newton method's residual in no_equilibrium_after_breaking_2_ranks
  # differed in its third digit.
  export OPENBLAS_NUM_THREADS=1
fi
# The same input on one process, for the comparison at the end (not for a
# signal, whose timing decides where the run ends).
if [ -n "$ranks" ] && ! grep -q '^# signal-on: ' "$input"; then
  compare=yes
  serial_work=$work.serial
  rm -rf "$serial_work" && mkdir -p "$serial_work" || exit 1
  (cd "$serial_work" &&
    { setup=$(sed -n 's/^# setup: //p' "$input"); [ -z "$setup" ] || bash -c "$setup"; } &&
    "$mbfem" "$run_input" > stdout 2> stderr; echo $? > status)
fi

rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
setup=$(sed -n 's/^# setup: //p' "$input")
[ -n "$setup" ] && { bash -c "$setup" || exit 1; }
signal_on=$(sed -n 's/^# signal-on: //p' "$input")
if [ -n "$signal_on" ]; then
  pattern=${signal_on% *}
  signal=${signal_on##* }
  "${launch[@]}" "$mbfem" "$run_input" > stdout 2> stderr &
  pid=$!
  for _ in $(seq 600); do
    grep -E -q -- "$pattern" stdout && break
    kill -0 $pid 2> /dev/null || break
    sleep 0.1
  done
  kill -s "$signal" $pid 2> /dev/null
  wait $pid
  status=$?
else
  "${launch[@]}" "$mbfem" "$run_input" > stdout 2> stderr
  status=$?
fi
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
while IFS= read -r pattern; do
  if grep -E -q -- "$pattern" stderr; then
    echo "FAIL: the error output matches what it must not: $pattern"
    failed=1
  fi
done < <(sed -n 's/^# expect-not: //p' "$input")
while IFS= read -r pattern; do
  if ! grep -E -q -- "$pattern" stdout; then
    echo "FAIL: the screen output does not match: $pattern"
    failed=1
  fi
done < <(sed -n 's/^# expect-stdout: //p' "$input")
if grep -E -q -- '^-{20,}|Stacktrace|An error occurred in line' stderr; then
  echo "FAIL: stderr holds a deal.II exception dump, not just the message"
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
while IFS= read -r pvd; do
  while IFS= read -r file; do
    if [ ! -s "$(dirname "$pvd")/$file" ]; then
      echo "FAIL: $pvd names $file, which is not on disk"
      failed=1
    fi
  done < <(sed -n 's/.* file="\([^"]*\)".*/\1/p' "$pvd")
done < <(find . -name '*.pvd')
if [ -n "$compare" ]; then
  if [ "$status" != "$(cat "$serial_work/status")" ]; then
    echo "FAIL: exit code $status on $ranks ranks, $(cat "$serial_work/status") on one process"
    failed=1
  fi
  if ! diff -u "$serial_work/stderr" stderr; then
    echo "FAIL: the error message on $ranks ranks differs from one process's"
    failed=1
  fi
fi
# '# ranks-compare: message': the files may differ (another rank may have
# written its blocks' files of the increment that failed).
if [ -n "$compare" ] && ! grep -q '^# ranks-compare: message' "$input"; then
  # The same files, with the same contents but for the summary's times.
  if ! diff <(cd "$serial_work" && find . -type f ! -name 'std*' ! -name status | sort) \
            <(find . -type f ! -name 'std*' | sort); then
    echo "FAIL: the files on $ranks ranks differ from one process's"
    failed=1
  fi
  while IFS= read -r file; do
    if ! cmp -s "$serial_work/$file" "$file"; then
      echo "FAIL: $file on $ranks ranks differs from one process's"
      failed=1
    fi
  done < <(find . -type f ! -name 'std*' ! -name '*summary*')
fi
[ $failed -eq 0 ] && echo "PASS: exit code $status, message as expected"
exit $failed
