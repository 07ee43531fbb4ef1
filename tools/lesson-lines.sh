#!/bin/bash
# lesson-lines.sh [--check] - what a student reads and writes, chapter by chapter.
#
# For each chapters/NN_name/: the lesson's stage code (the .c and .h files a
# student opens there, render.c aside), render.c, the program's given code
# beside it (renderer/*.c, renderer/*.h: option rows, the shading renderer),
# the lab (lab/*.c, lab/*.h), the README, and the lines the student writes (the
# non-blank lines of the solutions' exercise regions, tools/skeleton.awk's
# format).  With --check, fails naming every chapter past its budget and a
# course past its read-to-write ratio: the budgets are the table of
# docs/design.md ("Lesson and lab"), between <!-- budgets: and
# <!-- end budgets -->.
budgets=docs/design.md
check=0
[ "${1:-}" = --check ] && check=1
lines() { cat "$@" 2>/dev/null | wc -l; }
# The non-blank lines between an EXERCISE comment's end and its STUB.
written() {
    awk '/\/\* EXERCISE [A-Za-z0-9_]+:/ { s = ($0 ~ /\*\//) ? 2 : 1; next }
         s == 1 { if ($0 ~ /\*\//) s = 2; next }
         s == 2 && /^[ \t]*\/\* STUB[ \t]*$/ { s = 3; next }
         s == 2 && NF { n++ }
         s == 3 && /END EXERCISE \*\// { s = 0 }
         END { print n + 0 }' "$@" /dev/null
}
# The budget of chapter $1 in column $2 of the table (| chapter | lesson | render.c | renderer/ |).
budget() {
    awk -F'|' -v c="$1" -v col="$2" '/<!-- budgets:/ { on = 1 } /<!-- end budgets -->/ { on = 0 }
        on { name = $2; gsub(/ /, "", name); if (name == c) { v = $col; gsub(/ /, "", v); print v } }' "$budgets"
}
status=0
read_all=0
written_all=0
printf '%-18s %7s %7s %9s %7s %8s %7s\n' chapter lesson render.c renderer/ lab written README
for dir in chapters/[0-9][0-9]_*/; do
    c=$(basename "$dir")
    shopt -s nullglob
    stage=()
    for f in "$dir"*.c "$dir"*.h; do [ "$(basename "$f")" = render.c ] || stage+=("$f"); done
    shared=("$dir"renderer/*.c "$dir"renderer/*.h)
    lab=("$dir"lab/*.c "$dir"lab/*.h)
    sol=(solutions/"$c"/*.c)
    shopt -u nullglob
    l=$(lines "${stage[@]}")
    r=$(lines "$dir"render.c)
    s=$( ((${#shared[@]})) && lines "${shared[@]}" || echo 0)
    b=$( ((${#lab[@]})) && lines "${lab[@]}" || echo 0)
    w=$( ((${#sol[@]})) && written "${sol[@]}" || echo 0)
    m=$(lines "$dir"README.md)
    printf '%-18s %7d %7d %9d %7d %8d %7d\n' "$c" "$l" "$r" "$s" "$b" "$w" "$m"
    read_all=$((read_all + l))
    written_all=$((written_all + w))
    lesson_max=$(budget "$c" 3)
    render_max=$(budget "$c" 4)
    shared_max=$(budget "$c" 5)
    if [ -z "$lesson_max" ] || [ -z "$render_max" ] || [ -z "$shared_max" ]; then
        echo "$c: no budget in $budgets (\"Lesson and lab\")" >&2
        status=1
        continue
    fi
    if [ "$l" -gt "$lesson_max" ]; then
        echo "$c: the lesson's stage code is $l lines, past its budget of $lesson_max ($budgets): move what measures to lab/" >&2
        status=1
    fi
    if [ "$r" -gt "$render_max" ]; then
        echo "$c: render.c is $r lines, past its budget of $render_max ($budgets)" >&2
        status=1
    fi
    if [ "$s" -gt "$shared_max" ]; then
        echo "$c: renderer/ is $s lines, past its budget of $shared_max ($budgets)" >&2
        status=1
    fi
done
ratio=$(awk -v r="$read_all" -v w="$written_all" 'BEGIN { printf "%.1f", w ? r / w : 0 }')
echo "course: $read_all lines of stage code read for $written_all written: $ratio to 1"
ratio_max=$(budget course 3)
if [ -z "$ratio_max" ] || awk -v r="$read_all" -v w="$written_all" -v m="$ratio_max" 'BEGIN { exit !(w == 0 || r > m * w) }'; then
    echo "course: read-to-write ratio $ratio to 1, past its budget of ${ratio_max:-(none)} to 1 ($budgets)" >&2
    status=1
fi
# A lab stays readable file by file: none of its files (code and pages) passes LAB_FILE_MAX lines.
LAB_FILE_MAX=500
for f in chapters/[0-9][0-9]_*/lab/*; do
    [ -f "$f" ] || continue
    n=$(lines "$f")
    if [ "$n" -gt "$LAB_FILE_MAX" ]; then
        echo "$f: $n lines, past a lab file's $LAB_FILE_MAX ($budgets): split it by concept" >&2
        status=1
    fi
done
# The layers: the lesson reads neither the program's code beside it nor the lab
# (renderer/ and lab/ read the lesson), and renderer/ does not read the lab.
for f in chapters/[0-9][0-9]_*/*.[ch] solutions/[0-9][0-9]_*/*.c chapters/[0-9][0-9]_*/renderer/*.[ch]; do
    [ "$(basename "$f")" = render.c ] && continue
    case $f in */renderer/*) layer='lab/' ;; *) layer='renderer/|lab/' ;; esac
    if grep -HnE "^#include \"[0-9][0-9]_[a-z_0-9]+/($layer)" "$f" >&2; then
        echo "$f: includes what reads it (docs/design.md, \"Lesson and lab\")" >&2
        status=1
    fi
done
[ "$check" = 1 ] && exit "$status"
exit 0
