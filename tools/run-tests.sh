#!/bin/bash
# run-tests.sh RESULTS SUITE... - run cmocka suites, print and record counts.
#
# Each suite's exit status is its number of failed tests (cmocka's
# convention); a suite that dies from a signal counts all its tests as failed.
# RESULTS gets one line: "PASSED FAILED".
results=$1
shift
passed=0
failed=0
for suite in "$@"; do
    total=$("$suite" --list | wc -l)
    "$suite"
    status=$?
    if [ "$status" -gt "$total" ] || [ "$status" -lt 0 ]; then
        echo "$suite: crashed (exit status $status): all $total tests count as failed" >&2
        status=$total
    fi
    passed=$((passed + total - status))
    failed=$((failed + status))
done
echo "$passed $failed" >"$results"
echo "$(dirname "$results"): $passed passed, $failed failed"
[ "$failed" -eq 0 ]
