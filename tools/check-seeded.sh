#!/bin/bash
# check-seeded.sh SUITE... - every graded test checks inputs drawn at grading time.
#
# For each chapter's suite: every test worth points (`SUITE --list`) has a
# line in tests/seeded/NN_name.c (`SUITE --seeded`), every such line names
# a test of the suite (tests/answers.h), and each test run as the grader
# runs it (`--answers`, here with a fixed seed) passes and gives answers.
# Fails naming each that does not; a suite with no points (the suites of
# common/) is not checked.
status=0
records=$(mktemp)
trap 'rm -f "$records"' EXIT
for suite in "$@"; do
    tests=$("$suite" --list) || { echo "$suite: cannot list its tests" >&2; status=1; continue; }
    seeded=$("$suite" --seeded | sort -u)
    graded=$(printf '%s\n' "$tests" | awk '$2 > 0 { print $1 }' | sort -u)
    [ -n "$graded" ] || continue
    name=$(basename "$suite")
    for t in $(comm -23 <(echo "$graded") <(echo "$seeded")); do
        echo "$name: $t is worth points but has no check of inputs drawn at grading time (tests/seeded/${name#test_}.c)" >&2
        status=1
    done
    for t in $seeded; do
        "$suite" --only "$t" --answers 3 --seed 5eed 3>"$records" >/dev/null 2>&1
        if [ "$(tail -n 1 "$records")" != "end 0" ] || ! grep -q '^answer ' "$records"; then
            echo "$name: $t does not pass with its inputs drawn from a seed, or gives no answer" >&2
            status=1
        fi
    done
    for t in $(comm -13 <(printf '%s\n' "$tests" | awk '{ print $1 }' | sort -u) <(echo "$seeded") | grep .); do
        echo "$name: tests/seeded/${name#test_}.c names $t, which is no test of the suite" >&2
        status=1
    done
done
[ "$status" = 0 ] && echo "every graded test of $# suites checks inputs drawn at grading time"
exit $status
