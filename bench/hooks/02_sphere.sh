#!/bin/sh
# The far-sphere sweep of chapter 02 (test_far_spheres): rays misclassified
# by the textbook formula, and its worst hit error, per distance, in double
# and in float.  The robust formula's counts are all 0 (the suite requires it).
build=$1
fbuild=$2
suite=tests/test_02_sphere
for b in "$build" "$fbuild"; do
    real=double
    [ "$b" = "$fbuild" ] && real=float
    make -s --no-print-directory BUILD="$b" REAL=$real "$b/$suite" >&2 || exit 1
    "$b/$suite" --only test_far_spheres 2>&1 | awk -v real=$real '/^D\/R =/ {
        sub(/^D\/R = */, ""); d = $1; sub(/:$/, "", d)
        for (k = 1; k <= NF; k++) {
            if ($k == "textbook") { wrong = $(k + 1) }
            if ($k == "worst") { worst = $(k + 1) }
        }
        print real, d, wrong, worst
    }'
done >"${TMPDIR:-/tmp}/bench-02-sweep.$$" || exit 1
echo "The textbook quadratic formula against the robust one on the suite's far-sphere sweep"
echo "(\`test_far_spheres\`: 320 rays per distance, half clearly inside the silhouette, half clearly outside;"
echo "the robust formula misclassifies none and stays within 1.2 eps S of the surface at every distance):"
echo
echo "| D/R | double: rays wrong | double: worst hit error | float: rays wrong | float: worst hit error |"
echo "|---|---|---|---|---|"
awk '{ key = $2; if (!(key in seen)) { order[++n] = key; seen[key] = 1 } v[$1, key] = $3 " of 320 | " $4 " R" }
     END { for (k = 1; k <= n; k++) {
               d = order[k]; dd = ((("double", d) in v) ? v["double", d] : "| ")
               ff = ((("float", d) in v) ? v["float", d] : "not swept | -")
               print "| " d " | " dd " | " ff " |" } }' "${TMPDIR:-/tmp}/bench-02-sweep.$$"
rm -f "${TMPDIR:-/tmp}/bench-02-sweep.$$"
