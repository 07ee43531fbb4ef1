#!/bin/sh
# The precision limits of chapter 09 (its lab, lab --limits): total internal
# reflection decided on the wrong side of the critical angle, R + T = 1, and
# the refracted direction through a sphere's centre and a slab at every scale,
# in double and in float; then what --min-weight's cut drops, on a glass sphere
# against white.
build=$1
fbuild=$2
tmp=${TMPDIR:-/tmp}/bench-09-limits.$$
"$build/09_refraction/lab" --limits >"$tmp.d" || exit 1
"$fbuild/09_refraction/lab" --limits >"$tmp.f" || exit 1
worst() { # FILE KIND COLUMN: the largest value of COLUMN on the lines of KIND
    awk -v k="$2" -v c="$3" '$1 == k { x = $c + 0; if (n == 0 || x > w) { w = x; s = $c }; n++ } END { print (n ? s : "-") }' "$1"
}
upto() { awk '$1 == "eta_equal" && $3 + 0 <= 89.9 { x = $4 + 0; if (n == 0 || x > w) { w = x; s = $4 }; n++ } END { print (n ? s : "-") }' "$1"; }
nonfinite() { awk '$1 == "eta_equal" && ($4 ~ /inf|nan/) { print $3; f = 1; exit } END { if (!f) print "none" }' "$1"; }
lost() { awk -v k="$2" '$1 == k { n += $NF } END { print n + 0 }' "$1"; }
echo "Where the precision gives out in refraction (\`build/09_refraction/lab --limits\`, chapter 09's lab): the largest"
echo "distance from the critical angle at which total internal reflection was decided wrongly (0: never), the"
echo "worst |R + T - 1|, the worst refracted-direction error (radians) through a sphere's centre at scales"
echo "10^-4 to 10^8 and through a slab up to 89.9 degrees, and the rays lost there:"
echo
echo "| measure | double | float |"
echo "|---|---|---|"
echo "| critical angle: largest \|theta - theta_c\| decided wrongly (rad) | $(worst "$tmp.d" critical 3) | $(worst "$tmp.f" critical 3) |"
echo "| worst \|R + T - 1\| | $(worst "$tmp.d" r_plus_t 3) | $(worst "$tmp.f" r_plus_t 3) |"
echo "| equal indices, up to 89.9 degrees: worst \|T - d\| | $(upto "$tmp.d") | $(upto "$tmp.f") |"
echo "| equal indices: first angle with a non-finite T (degrees) | $(nonfinite "$tmp.d") | $(nonfinite "$tmp.f") |"
echo "| through the centre: worst angle (rad) | $(worst "$tmp.d" centre 4) | $(worst "$tmp.f" centre 4) |"
echo "| slab: worst angle (rad) | $(worst "$tmp.d" slab 5) | $(worst "$tmp.f" slab 5) |"
echo "| rays lost (centre + slab) | $(($(lost "$tmp.d" centre) + $(lost "$tmp.d" slab))) | $(($(lost "$tmp.f" centre) + $(lost "$tmp.f" slab))) |"

# What --min-weight drops: the glass sphere in front of white (chapters/09_refraction/scenes/glass-on-white.xml),
# which is invisible when nothing is cut off.  Each setting against --min-weight=0 of the same build.
imgcmp=$build/bench-tools/imgcmp
scene=chapters/09_refraction/scenes/glass-on-white.xml
secondary() { # LOG: the reflected and refracted rays of a renderer's summary line
    sed -n 's/.* eye + \([0-9]*\) reflected + \([0-9]*\) refracted rays.*/\1 \2/p' "$1" | awk '{ print $1 + $2 }'
}
for b in "$build" "$fbuild"; do
    "$b/09_refraction/render" -q --min-weight=0 -o "$tmp.$(basename "$b").0.png" "$scene" || exit 1
done
echo
echo "What \`--min-weight\` drops: a glass sphere (η 1.5) in front of a white background, 512x512, which shows"
echo "nothing when nothing is cut off; each setting against \`--min-weight=0\` of the same build (pixels that"
echo "differ, the largest difference in levels of 0-255, the RMSE in levels):"
echo
echo "| --min-weight | double: secondary rays | pixels off | largest | RMSE | float: pixels off | largest | RMSE |"
echo "|---|---|---|---|---|---|---|---|"
for w in 1e-2 1e-3 1e-4; do
    row="| $w$([ $w = 1e-3 ] && echo " (default)")"
    for b in "$build" "$fbuild"; do
        name=$(basename "$b")
        "$b/09_refraction/render" --min-weight=$w -o "$tmp.$name.png" "$scene" >"$tmp.log" 2>&1 || exit 1
        [ "$b" = "$build" ] && row="$row | $(secondary "$tmp.log")"
        row="$row | $("$imgcmp" "$tmp.$name.png" "$tmp.$name.0.png" | awk '{ print $3 " | " $2 " | " $6 }')"
    done
    echo "$row |"
done
"$build/09_refraction/render" --min-weight=0 -o "$tmp.png" "$scene" >"$tmp.log" 2>&1 || exit 1
echo "| 0 | $(secondary "$tmp.log") | | | | | | |"
rm -f "$tmp".*
