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
    total=$("$suite" --list | wc -l)
    "$suite" 2>&1 | tee "$log"
    status=${PIPESTATUS[0]}
    if [ "$status" -gt "$total" ] || [ "$status" -lt 0 ]; then
        echo "$suite: crashed (exit status $status): all $total tests count as failed" >&2
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
