#!/bin/bash
# sum-results.sh BUILD... - add up the counts that run-tests.sh recorded.
passed=0
failed=0
for build in "$@"; do
    read -r p f <"$build/test-results.txt" || { echo "$build: no results" >&2; exit 1; }
    passed=$((passed + p))
    failed=$((failed + f))
done
echo "total: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
