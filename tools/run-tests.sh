#!/bin/bash
# run-tests.sh RESULTS SUITE... - run cmocka suites, print and record counts.
#
# Each suite's exit status is its number of failed tests (cmocka's
# convention); a suite that dies from a signal counts all its tests as failed.
# Skipped tests (the Cornell corpus absent) are counted apart from the passed.
# RESULTS gets one line: "PASSED FAILED SKIPPED".
results=$1
shift
passed=0
failed=0
skipped=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for suite in "$@"; do
    if ! total=$("$suite" --list | wc -l) || [ "$total" -eq 0 ]; then
        echo "$suite: cannot list its tests: counted as one failed test" >&2
        failed=$((failed + 1))
        continue
    fi
    "$suite" 2>&1 | tee "$log"
    status=${PIPESTATUS[0]}
    ran=$(sed -n 's/^\[==========\] \([0-9]*\) test(s) run\.$/\1/p' "$log")
    if [ "$status" -gt "$total" ] || [ "${ran:-0}" -ne "$total" ]; then
        echo "$suite: crashed (exit status $status) after ${ran:-0} of $total tests: all count as failed" >&2
        status=$total
    fi
    s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test(s), listed below:$/\1/p' "$log")
    s=${s:-0}
    passed=$((passed + total - status - s))
    failed=$((failed + status))
    skipped=$((skipped + s))
done
echo "$passed $failed $skipped" >"$results"
echo "$(dirname "$results"): $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
