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
