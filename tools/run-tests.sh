#!/bin/bash
# run-tests.sh RESULTS SUITE... - run cmocka suites, print and record counts.
#
# Each suite's exit status is its number of failed tests (cmocka's
# convention); a suite that dies from a signal counts all its tests as failed.
# Skipped tests (the Cornell corpus absent) are counted apart from the passed.
# RESULTS gets one line: "PASSED FAILED SKIPPED".
#
# Each suite's whole output goes to a log beside RESULTS (logs/SUITE.log) and
# the suite gets one line: its counts, and when it fails the names of the
# failed tests and the log to read.  With V=1 the whole output is shown too,
# after a line naming the suite.
results=$1
shift
logs=$(dirname "$results")/logs
mkdir -p "$logs" || exit 1
passed=0
failed=0
skipped=0
for suite in "$@"; do
    log=$logs/$(basename "$suite").log
    if ! total=$("$suite" --list | wc -l) || [ "$total" -eq 0 ]; then
        echo "  FAIL    $suite: cannot list its tests: counted as one failed test" >&2
        failed=$((failed + 1))
        continue
    fi
    if [ "${V:-0}" = 1 ]; then
        echo "==== $suite"
        "$suite" 2>&1 | tee "$log"
        status=${PIPESTATUS[0]}
    else
        "$suite" >"$log" 2>&1
        status=$?
    fi
    ran=$(sed -n 's/^\[==========\] \([0-9]*\) test(s) run\.$/\1/p' "$log")
    crashed=""
    if [ "$status" -gt "$total" ] || [ "${ran:-0}" -ne "$total" ]; then
        crashed="crashed (exit status $status) after ${ran:-0} of $total tests: all count as failed; "
        status=$total
    fi
    s=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test(s), listed below:$/\1/p' "$log")
    s=${s:-0}
    passed=$((passed + total - status - s))
    failed=$((failed + status))
    skipped=$((skipped + s))
    counts="$((total - status - s)) passed$([ "$s" -gt 0 ] && echo ", $s skipped")"
    if [ "$status" -eq 0 ]; then
        echo "  PASS    $suite: $counts"
    else
        names=$(sed -n 's/^\[  FAILED  \] \([A-Za-z_0-9]*\)$/\1/p' "$log" | sort -u | tr '\n' ' ')
        echo "  FAIL    $suite: $crashed$status of $total failed: ${names:-(none named)}(output: $log)"
    fi
done
echo "$passed $failed $skipped" >"$results"
echo "$(dirname "$results"): $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
