#!/bin/sh
# run.sh BENCH - the grid against the linear scan and Embree: the Stanford
# bunny of Debian's glmark2-data, then a procedural sphere of 1 million
# triangles, 512x512 primary rays each; then the bunny again with as many
# incoherent rays (origins in its box, directions uniform).  The linear scan
# takes every 64-th row of the bunny (8 rows, 4096 rays) and none of the rest.
bench=$1
bunny=$(dpkg -L glmark2-data 2>/dev/null | grep '/bunny\.obj$' | head -n 1)
if [ -z "$bunny" ] || [ ! -r "$bunny" ]; then
    echo "bench-grid: the bunny of glmark2-data is not installed (make bench-grid installs it through tools/deps.sh)" >&2
    exit 1
fi
# BENCH_GRID_QUICK=1 (make bench, within its ten minutes): the bunny only, one run per timing.
if [ "${BENCH_GRID_QUICK:-0}" = 1 ]; then
    "$bench" "$bunny" --size 512 --linear-rows 64 --runs 1 || exit 1
    exit 0
fi
"$bench" "$bunny" --size 512 --linear-rows 64 || exit 1
echo
"$bench" sphere:1000000 --size 512 --linear-rows 0 || exit 1
echo
"$bench" "$bunny" --size 512 --linear-rows 0 --knobs 0 --random || exit 1
