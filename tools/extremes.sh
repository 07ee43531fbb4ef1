#!/bin/sh
# extremes.sh BUILD - every chapter's renderer over the scenes at the
# extremes (tests/extremes/), the chapters' own scenes and, when present, the
# Cornell corpus's, each small (32x24, 4 samples per pixel), with
# --nonfinite=fail: a sample whose radiance is NaN or infinite fails the
# render, and so does a crash or (in the sanitizer build) undefined behaviour.
# Chapter 01 also renders each with --show=floor.
build=$1
cornell=${RT_CORNELL:-../shared/cornell/sp17-ray1/data}
out=$(mktemp -d) || exit 1
trap 'rm -rf "$out"' EXIT
set -- tests/extremes/*.xml chapters/*/scenes/*.xml
if [ -d "$cornell/scenes/ray1" ]; then
    set -- "$@" "$cornell"/scenes/ray1/*.xml
else
    echo "extremes: the Cornell corpus ($cornell) is absent: its scenes are not rendered"
fi
status=0
count=0
for renderer in "$build"/[0-9][0-9]_*/render; do
    chapter=$(basename "$(dirname "$renderer")")
    for scene in "$@"; do
        for show in "" --show=floor; do
            [ -n "$show" ] && [ "$chapter" != 01_camera_rays ] && continue
            if ! "$renderer" -q --nonfinite=fail -s 32x24 -n 4 $show -o "$out/image.png" "$scene" \
                    >"$out/log" 2>&1 </dev/null; then
                echo "extremes: $chapter $show $scene failed:" >&2
                cat "$out/log" >&2
                status=1
            fi
            count=$((count + 1))
        done
    done
done
[ "$status" = 0 ] && echo "extremes: $count renders in $build, no NaN or infinite sample"
exit $status
