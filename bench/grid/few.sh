#!/bin/sh
# few.sh LAB [ROUNDS] - where a list beats the fast grid's cells: scenes of a
# floor (a box) and k boxes, spheres or triangles standing on it, rendered by
# chapter 11's lab (build/11_grid/lab) as a list (--list-up-to=100000) and in
# cells (--list-up-to=0), one thread, 640 x 360, the two in turn, ROUNDS
# rounds (9).  Prints the medians of the trace times ("traced in") and checks
# that the two images are the same bytes.  The lab's README ("Few surfaces")
# takes fast_few.c's weights from this table.
lab=${1:?usage: few.sh build/11_grid/lab [rounds]}
rounds=${2:-9}
case $rounds in '' | *[!0-9]* | 0) echo "few.sh: rounds must be a positive count" >&2; exit 2 ;; esac
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT

# scene KIND K: the floor and K shapes of KIND on a 4 x 4 lattice over it, sizes 0.3 to 0.8
scene() {
    awk -v kind="$1" -v k="$2" 'BEGIN {
        print "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<scene>\n<backColor>.9 .2 .2</backColor>"
        print "<camera type=\"PerspectiveCamera\"><viewPoint>10 4.8 6</viewPoint><viewDir>-5 -2.4 -3</viewDir>"
        print "<viewUp>0 1 0</viewUp><projDistance>6</projDistance><viewWidth>4</viewWidth><viewHeight>2.25</viewHeight></camera>"
        print "<image>640 360</image>"
        print "<shader name=\"blue\" type=\"Lambertian\"><diffuseColor>.2 .3 1</diffuseColor></shader>"
        print "<shader name=\"gray\" type=\"Lambertian\"><diffuseColor>.5 .5 .5</diffuseColor></shader>"
        print "<surface type=\"Box\"><shader ref=\"gray\" /><minPt>-5 -1.1 -6</minPt><maxPt>5 -1 6</maxPt></surface>"
        for (i = 0; i < k; i++) {
            x = -3.3 + 2.2 * (i % 4); z = -3.9 + 2.6 * (int(i / 4) % 4); s = 0.3 + 0.5 * ((i * 7) % 11) / 10
            if (kind == "box")
                printf "<surface type=\"Box\"><shader ref=\"blue\" /><minPt>%.3f -1 %.3f</minPt><maxPt>%.3f %.3f %.3f</maxPt></surface>\n", x - s, z - s, x + s, -1 + 2 * s, z + s
            else if (kind == "sphere")
                printf "<surface type=\"Sphere\"><shader ref=\"blue\" /><center>%.3f %.3f %.3f</center><radius>%.3f</radius></surface>\n", x, -1 + s, z, s
            else
                printf "<surface type=\"Triangle\"><shader ref=\"blue\" /><v0>%.3f -1 %.3f</v0><v1>%.3f %.3f %.3f</v1><v2>%.3f -1 %.3f</v2></surface>\n", x - s, z, x, -1 + 2 * s, z + 0.1, x + s, z + 0.2
        }
        print "<light><position>4 5 -3</position><intensity>14 14 14</intensity></light>"
        print "<light><position>-4 3 5</position><intensity>6 6 6</intensity></light>\n</scene>"
    }'
}

traced() { "$lab" -j 1 "$@" 2>&1 | sed -n 's/.*traced in \([0-9.]*\) s.*/\1/p'; }
median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "kind     shapes  units  list s  cells s  (medians of $rounds rounds, 640 x 360, 1 thread)"
for kind in box sphere triangle; do
    for k in 0 1 2 3 4 5 6 7 8 10 12 15; do
        xml=$work/$kind$k.xml
        scene $kind $k >"$xml"
        : >"$work/list.t"
        : >"$work/cells.t"
        r=0
        while [ $r -lt "$rounds" ]; do
            traced --list-up-to=100000 -o "$work/list.png" "$xml" >>"$work/list.t"
            traced --list-up-to=0 -o "$work/cells.png" "$xml" >>"$work/cells.t"
            r=$((r + 1))
        done
        cmp -s "$work/list.png" "$work/cells.png" || { echo "few.sh: $kind $k: the images differ" >&2; exit 1; }
        printf '%-8s %6d %6d  %6s  %7s\n' $kind $k $((k + 1)) "$(median <"$work/list.t")" "$(median <"$work/cells.t")"
    done
done
