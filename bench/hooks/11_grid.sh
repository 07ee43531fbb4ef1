#!/bin/sh
# Chapter 11's grid against chapter 04's linear scan (render --accel=list) on
# the same rays: the pixels whose colour differs (the grid must report the
# scan's closest hit bit for bit, so every count is 0), and both trace times.
# Small sizes: the linear scan over a mesh is slow.
build=$1
render=$build/11_grid/render
imgcmp=$build/bench-tools/imgcmp
cornell=${RT_CORNELL:-../shared/cornell/sp17-ray1/data}/scenes/ray1
tmp=${TMPDIR:-/tmp}/bench-11-grid.$$
secs() { sed -n 's/.*rays, .* \([0-9.]*\) s, .*/\1/p' "$1" | head -n 1; }
echo "The grid against chapter 04's linear scan (\`--accel=list\`), same scene, size and rays, 2 threads:"
echo "the pixels that differ (the grid must find the scan's closest hit bit for bit: 0 everywhere), and the"
echo "render loop's time of each (a rough ratio: one run each on a shared machine)."
echo
echo "| scene | size | pixels that differ | grid | linear scan |"
echo "|---|---|---|---|---|"
row() { # LABEL SIZE [SCENE]
    label=$1 size=$2
    shift 2
    "$render" -j 2 -s "$size" --accel=grid -o "$tmp.g.png" "$@" >"$tmp.g.log" 2>&1 || { echo "| $label | $size | grid failed | | |"; return; }
    "$render" -j 2 -s "$size" --accel=list -o "$tmp.l.png" "$@" >"$tmp.l.log" 2>&1 || { echo "| $label | $size | list failed | | |"; return; }
    diff=$("$imgcmp" "$tmp.g.png" "$tmp.l.png" | awk '{ print $3 " of " $4 }')
    echo "| $label | $size | ${diff:-failed} | $(secs "$tmp.g.log") s | $(secs "$tmp.l.log") s |"
}
row "built-in scene" 96x96
row "bench/scenes/stages.xml" 160x120 bench/scenes/stages.xml
for s in bunny teapot two-boxes wire-box; do
    [ -f "$cornell/$s.xml" ] && row "course: $s.xml" 64x64 "$cornell/$s.xml"
done
rm -f "$tmp".*
