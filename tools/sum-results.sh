#!/bin/bash
# sum-results.sh BUILD... - add up the counts that run-tests.sh recorded.
passed=0
failed=0
skipped=0
for build in "$@"; do
    read -r p f s <"$build/test-results.txt" || { echo "$build: no results" >&2; exit 1; }
    passed=$((passed + p))
    failed=$((failed + f))
    skipped=$((skipped + ${s:-0}))
done
echo "total: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
