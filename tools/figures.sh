#!/bin/sh
# figures.sh render|check BUILD LIST... - the lecture figures of the chapters.
#
# Each LIST is a chapters/NN_name/figures.txt; each of its lines (blank lines
# and lines starting with # aside) is
#
#     OUTPUT.png REAL ARGS...
#
# and is rendered by the chapter's renderer of the REAL (double or float)
# build, BUILD/NN_name/render or BUILD-float/NN_name/render, as
#
#     render -q --nonfinite=fail -o docs/figures/OUTPUT.png ARGS...
#
# A plot is the line `OUTPUT.png gnuplot SCRIPT.gp`, drawn as
#
#     gnuplot -e "output='docs/figures/OUTPUT.png'; build='BUILD'" SCRIPT.gp
#
# (the script may run the renderers and labs of BUILD and BUILD-float for its
# data).  REAL double-lab or float-lab renders with the chapter's lab,
# BUILD/NN_name/lab, in place of its renderer.
#
# @CORNELL@ in ARGS is the Cornell corpus folder; a figure that needs it is
# skipped, with a note, when the folder is absent.  An OUTPUT named @NAME.png
# is a panel: rendered into a scratch folder for the lines below, not kept.
# A line
#
#     OUTPUT.png panels IMAGE LABEL WORDS | IMAGE LABEL WORDS | ...
#
# puts the IMAGEs (panels @NAME.png, or figures of earlier lines) side by
# side, each under its label, by BUILD/tools/panels (tools/panels.c).
# `render` writes into docs/figures/; `check` renders into a temporary folder
# and fails naming every committed figure that is stale (not byte for byte
# the same) or missing.
mode=$1
build=$2
shift 2
case "$mode" in render|check) ;; *) echo "usage: $0 render|check BUILD LIST..." >&2; exit 2 ;; esac
cornell=${RT_CORNELL:-../shared/cornell/sp17-ray1/data}
figures=docs/figures
panels_tool=$build/tools/panels
scratch=$(mktemp -d) || exit 1
if [ "$mode" = check ]; then
    out=$scratch/check
    mkdir -p "$out"
else
    out=$figures
    mkdir -p "$out"
fi
trap 'rm -rf "$scratch"' EXIT

# The file of an image named on a panels line.
image_file() {
    case "$1" in
        @*) printf '%s\n' "$scratch/${1#@}" ;;
        *) printf '%s\n' "$out/$1" ;;
    esac
}

# compare NAME LIST:LINE - in check mode, the rendered figure against the committed one.
compare() {
    if [ "$mode" = check ]; then
        if [ ! -e "$figures/$1" ]; then
            echo "$figures/$1: missing (listed in $2; run make figures)" >&2
            status=1
        elif ! cmp -s "$out/$1" "$figures/$1"; then
            echo "$figures/$1: stale, it differs from what $2 renders (run make figures)" >&2
            status=1
        fi
    else
        echo "rendered $out/$1"
    fi
}
status=0
count=0
for list in "$@"; do
    chapter=$(basename "$(dirname "$list")")
    lineno=0
    while IFS= read -r line || [ -n "$line" ]; do
        lineno=$((lineno + 1))
        case "$line" in ''|'#'*) continue ;; esac
        set -f
        # shellcheck disable=SC2086
        set -- $line
        set +f
        name=$1
        real=$2
        if [ "$real" = panels ]; then
            # IMAGE LABEL WORDS | IMAGE LABEL WORDS | ...: split on |, then the first word.
            spec=${line#*panels}
            set --
            rest=$spec
            while [ -n "$rest" ]; do
                field=${rest%%|*}
                case "$rest" in *'|'*) rest=${rest#*|} ;; *) rest= ;; esac
                field=$(printf '%s' "$field" | sed 's/^ *//; s/ *$//')
                image=${field%% *}
                label=${field#"$image"}
                label=${label# }
                if [ -z "$image" ] || [ -z "$label" ] || [ "$image" = "$field" ]; then
                    echo "$list:$lineno: each panel is 'IMAGE LABEL WORDS', separated by |; got '$field'" >&2
                    status=1
                    continue 2
                fi
                file=$(image_file "$image")
                if [ ! -e "$file" ]; then
                    echo "$list:$lineno: $image is not rendered by an earlier line" >&2
                    status=1
                    continue 2
                fi
                set -- "$@" "$file" "$label"
            done
            if ! "$panels_tool" "$out/$name" "$@"; then
                echo "$list:$lineno: $panels_tool failed to put together $name" >&2
                status=1
                continue
            fi
            count=$((count + 1))
            compare "$name" "$list:$lineno"
            continue
        fi
        case "$real" in
            double) renderer=$build/$chapter/render ;;
            float) renderer=$build-float/$chapter/render ;;
            double-lab) renderer=$build/$chapter/lab ;;
            float-lab) renderer=$build-float/$chapter/lab ;;
            gnuplot) renderer=gnuplot ;;
            *) echo "$list:$lineno: the build must be double, float, double-lab, float-lab or gnuplot, not '$real'" >&2; status=1; continue ;;
        esac
        case "$name" in
            *.png) ;;
            *) echo "$list:$lineno: '$name' is not a .png name" >&2; status=1; continue ;;
        esac
        shift 2
        needs_cornell=0
        for arg in "$@"; do
            case "$arg" in *@CORNELL@*) needs_cornell=1 ;; esac
        done
        if [ "$needs_cornell" = 1 ] && [ ! -d "$cornell" ]; then
            echo "$name: skipped, the Cornell corpus ($cornell) is absent"
            continue
        fi
        # Expand @CORNELL@ in place, keeping each argument a single word.
        first=1
        for arg in "$@"; do
            expanded=$(printf '%s\n' "$arg" | sed "s|@CORNELL@|$cornell|g")
            if [ "$first" = 1 ]; then set --; first=0; fi
            set -- "$@" "$expanded"
        done
        [ "$first" = 1 ] && set --
        case "$name" in
            @*) target=$scratch/${name#@} ;;
            *) target=$out/$name ;;
        esac
        if [ "$real" = gnuplot ]; then
            if ! gnuplot -e "output='$target'; build='$build'" "$@" </dev/null; then
                echo "$list:$lineno: gnuplot failed to draw $name" >&2
                status=1
                continue
            fi
        elif ! "$renderer" -q --nonfinite=fail -o "$target" "$@" </dev/null; then
            echo "$list:$lineno: $renderer failed to render $name" >&2
            status=1
            continue
        fi
        case "$name" in @*) continue ;; esac
        count=$((count + 1))
        compare "$name" "$list:$lineno"
    done <"$list"
done
if [ "$mode" = check ] && [ "$status" = 0 ]; then
    echo "figures: all $count rendered figures match docs/figures/"
fi
exit $status
