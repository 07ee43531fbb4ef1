#!/bin/sh
# The crack count of chapter 03 (its lab, lab --cracks=64): rays aimed exactly at
# the edges and vertices of an icosahedron from inside that slip through,
# for each triangle test, in double and in float.
build=$1
fbuild=$2
echo "Rays aimed exactly at the edges and vertices of the unit icosahedron from 100 points inside it"
echo "(\`build/03_triangle/lab --cracks=64\`) that slip through between the faces:"
echo
echo "| test | double | float |"
echo "|---|---|---|"
for test in cramer watertight; do
    row="| $test |"
    for b in "$build" "$fbuild"; do
        line=$("$b/03_triangle/lab" --triangle=$test --cracks=64 -s 8x8 -o "${TMPDIR:-/tmp}/bench-03-cracks.$$.png" 2>&1 | grep 'slip through')
        count=$(printf '%s\n' "$line" | sed -n 's/.*: \([0-9]*\) of \([0-9]*\) rays.*/\1 of \2/p')
        row="$row ${count:-failed} |"
    done
    echo "$row"
done
rm -f "${TMPDIR:-/tmp}/bench-03-cracks.$$.png"

# The crossing check of common/crossing.c against the distance from the origin
# (lab --degenerate=N): false hits (a point further than 1 % of an edge
# from the triangle) at degenerate triangles and by rays in the plane, and
# clear hits that Cramer's rule alone decides but the test loses.
n=20000
echo
echo "Triangles of size 1 at a distance from the origin (\`build/03_triangle/lab --degenerate=$n\`): false hits of the"
echo "$((2 * n)) rays at degenerate triangles and in the plane (a point further than 1 % of an edge from the"
echo "triangle), and the clear hits lost (1 % inside, placed by Cramer's rule alone to within 1/1024 of an edge):"
echo
echo "| test, build | 0 | 10 | 10^2 | 10^3 | 10^4 | 10^5 | 10^6 |"
echo "|---|---|---|---|---|---|---|---|"
for test in cramer watertight; do
    for b in "$build" "$fbuild"; do
        name=double
        [ "$b" = "$fbuild" ] && name=float
        "$b/03_triangle/lab" --triangle=$test --degenerate=$n -s 8x8 -o "${TMPDIR:-/tmp}/bench-03-rates.$$.png" 2>&1 |
            awk -v label="$test, $name" '/at distance/ {
                sub(/.*: at distance [^:]*: /, ""); split($0, w, " ")
                lost = $0; sub(/.*; /, "", lost); sub(/ clear hits lost/, "", lost)
                row = row " " w[1] " / " lost " |"
            } END { print "| " label " (false / lost of clear) |" row }'
    done
done
rm -f "${TMPDIR:-/tmp}/bench-03-rates.$$.png"
