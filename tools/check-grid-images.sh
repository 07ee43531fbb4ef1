#!/bin/sh
# check-grid-images.sh BUILD [SIZE] - chapter 11's grid changes no pixel.
#
# Chapter 11's renderer is chapter 10's stage with the grid as its
# closest-hit query; its lab renders the same through the fast grid.
# Renders every scene of the Cornell corpus and every scene file of chapters
# 04-10 by chapter 10's renderer, by chapter 11's and by its lab's, and
# chapter 11's built-in scene through both grids and through the linear scan
# (--accel=list, chapter 10's query), and fails naming each pair of PNGs that
# are not byte for byte the same.  (The built-in scenes of chapters 05-10 are
# compared in the same way by tests/test_11_grid.c and tests/lab_11_grid.c.)  SIZE (WxH,
# default 160x160) keeps the linear scan of the big meshes short; SIZE=scene
# renders each scene at its own size.  The corpus is skipped, with a note,
# when absent.
build=$1
size=${2:-160x160}
cornell=${RT_CORNELL:-../shared/cornell/sp17-ray1/data}
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
status=0
count=0
opt=""
[ "$size" != scene ] && opt="-s $size"
same() { # name, a.png, b.png
    count=$((count + 1))
    if ! cmp -s "$2" "$3"; then
        echo "check-grid-images: $1: chapter 11's image differs from chapter 10's" >&2
        status=1
    fi
}
both() { # scene: chapter 10's renderer, chapter 11's (the lesson's grid) and its lab's (the fast grid)
    # shellcheck disable=SC2086
    "$build/10_interpolation/render" -q $opt -o "$tmp/10.png" "$1" &&
        "$build/11_grid/render" -q $opt -o "$tmp/11.png" "$1" &&
        "$build/11_grid/lab" -q --accel=fast $opt -o "$tmp/fast.png" "$1" || { status=1; return; }
    same "$1" "$tmp/10.png" "$tmp/11.png"
    same "$1 (fast grid)" "$tmp/10.png" "$tmp/fast.png"
}
# shellcheck disable=SC2086
"$build/11_grid/render" -q $opt -o "$tmp/grid.png" && "$build/11_grid/render" -q --accel=list $opt -o "$tmp/list.png" &&
    "$build/11_grid/lab" -q $opt -o "$tmp/fast.png" || exit 1
same "built-in scene" "$tmp/grid.png" "$tmp/list.png"
same "built-in scene (fast grid)" "$tmp/fast.png" "$tmp/list.png"
for scene in chapters/0[4-9]_*/scenes/*.xml chapters/10_*/scenes/*.xml; do
    [ -f "$scene" ] && both "$scene"
done
if [ -d "$cornell/scenes" ]; then
    for scene in "$cornell"/scenes/*/*.xml; do
        both "$scene"
    done
elif [ -n "$RT_REQUIRE_CORNELL" ]; then
    echo "check-grid-images: the Cornell corpus ($cornell) is absent" >&2
    status=1
else
    echo "check-grid-images: the Cornell corpus ($cornell) is absent: only the chapters' scenes compared"
fi
[ "$status" = 0 ] && echo "check-grid-images: $count images of chapter 11 byte for byte chapter 10's ($size)"
exit $status
