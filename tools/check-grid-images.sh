#!/bin/sh
# check-grid-images.sh BUILD [SIZE] - chapter 11's grid changes no pixel.
#
# Renders the built-in scene of chapter 11 through its grid and through
# chapter 04's linear scan (--accel=list), and every scene of the Cornell
# corpus by chapter 04's renderer and by chapter 11's, and fails naming each
# pair of PNGs that are not byte for byte the same.  SIZE (WxH, default
# 160x160) keeps the linear scan of the big meshes short; SIZE=scene renders
# each scene at its own size.  The corpus is skipped, with a note, when absent.
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
        echo "check-grid-images: $1: chapter 11's image differs from the linear scan's" >&2
        status=1
    fi
}
# shellcheck disable=SC2086
"$build/11_grid/render" -q $opt -o "$tmp/grid.png" && "$build/11_grid/render" -q --accel=list $opt -o "$tmp/list.png" ||
    exit 1
same "built-in scene" "$tmp/grid.png" "$tmp/list.png"
if [ -d "$cornell/scenes" ]; then
    for scene in "$cornell"/scenes/*/*.xml; do
        # shellcheck disable=SC2086
        "$build/04_many_shapes/render" -q $opt -o "$tmp/04.png" "$scene" &&
            "$build/11_grid/render" -q $opt -o "$tmp/11.png" "$scene" || { status=1; continue; }
        same "$scene" "$tmp/04.png" "$tmp/11.png"
    done
elif [ -n "$RT_REQUIRE_CORNELL" ]; then
    echo "check-grid-images: the Cornell corpus ($cornell) is absent" >&2
    status=1
else
    echo "check-grid-images: the Cornell corpus ($cornell) is absent: only the built-in scene compared"
fi
[ "$status" = 0 ] && echo "check-grid-images: $count images of chapter 11 byte for byte the linear scan's ($size)"
exit $status
