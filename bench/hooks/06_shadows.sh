#!/bin/sh
# The acne and leak measurement of chapter 06 (its lab, lab --acne-table): for each
# shadow-ray policy, shape and scale, the share of lit points that shadow
# themselves (acne) and of shadowed points that see the light (leak), in
# double and in float.
build=$1
fbuild=$2
tmp=${TMPDIR:-/tmp}/bench-06-acne.$$
"$build/06_shadows/lab" --acne-table >"$tmp.d" || exit 1
"$fbuild/06_shadows/lab" --acne-table >"$tmp.f" || exit 1
echo "Acne and leaks of each shadow-ray policy (\`build/06_shadows/lab --acne-table\`, chapter 06's lab): a square and a"
echo "sphere of size s, 64 x 64 points seen from above, shadow rays to a light above; acne is the share of"
echo "lit points that shadow themselves, leak the share of points under an occluder 10^-4 s away that see"
echo "the light.  \`% acne / % leak\`:"
echo
echo "| policy | shape | scale | double | float |"
echo "|---|---|---|---|---|"
# Lines "BUILD POLICY SHAPE SCALE ACNE LEAK"; the float file in the same order.
paste -d' ' "$tmp.d" "$tmp.f" | awk '{ print "| " $2 " | " $3 " | " $4 " | " $5 " / " $6 " | " $11 " / " $12 " |" }'
rm -f "$tmp.d" "$tmp.f"
