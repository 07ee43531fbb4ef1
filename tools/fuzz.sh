#!/bin/bash
# fuzz.sh BUILD SECONDS TARGET... - run each libFuzzer target for SECONDS.
#
# Target T is BUILD/fuzz_T.  It starts from its seeds in fuzz/corpus/T/ (the
# scene target also from the chapters' scenes, chapters/*/scenes/) and keeps
# what it learns in BUILD/corpus/T/, so the repository is never written to.
# One job at a time (-jobs is not used): the machine is shared.  A crash, a
# leak, a hang (over 10 s) or an input needing over 2 GB is saved as
# BUILD/findings/T/crash-*, timeout-*, leak-* or oom-*; the run then fails
# naming it.  To keep a finding for good, fix it, then copy the file into
# fuzz/corpus/T/ so that `make test` replays it (docs/fuzzing.md).
build=$1
seconds=$2
shift 2
status=0
for target in "$@"; do
    corpus=$build/corpus/$target
    findings=$build/findings/$target
    mkdir -p "$corpus" "$findings"
    seeds=(fuzz/corpus/"$target")
    [ "$target" = scene ] && seeds+=(chapters/*/scenes)
    log=$build/fuzz-$target.log
    echo "fuzzing $target for $seconds s (log: $log)"
    "$build/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
        -dict="fuzz/$target.dict" -artifact_prefix="$findings/" -print_final_stats=1 \
        "$corpus" "${seeds[@]}" >"$log" 2>&1
    result=$?
    # The summary: executions, edges covered of those instrumented, corpus.
    edges=$(sed -n 's/^INFO: Loaded [0-9]* modules *(\([0-9]*\) inline 8-bit counters).*/\1/p' "$log" | head -n 1)
    last=$(grep -E '^#[0-9]+' "$log" | tail -n 1)
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    cov=$(printf '%s\n' "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')
    echo "  $target: ${runs:-?} executions, ${cov:-?} of ${edges:-?} edges covered, $(ls "$corpus" | wc -l) corpus inputs"
    if [ "$result" -ne 0 ] || [ -n "$(ls -A "$findings")" ]; then
        echo "  $target: FOUND something (exit status $result):" >&2
        ls "$findings" >&2
        grep -E '^(==[0-9]+==ERROR|SUMMARY|contract broken|input:)' "$log" | head -n 5 >&2
        status=1
    fi
done
exit $status
