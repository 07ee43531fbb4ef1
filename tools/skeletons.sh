#!/bin/sh
# skeletons.sh write|check SOLUTION... - the students' skeletons from the solutions.
#
# For each solutions/NN_name/FILE.c, tools/skeleton.awk makes the skeleton
# chapters/NN_name/FILE.c.  `write` replaces the skeletons that differ;
# `check` changes nothing and fails naming each skeleton that differs from
# what generation produces, or is missing.
mode=$1
shift
case "$mode" in write|check) ;; *) echo "usage: $0 write|check SOLUTION..." >&2; exit 2 ;; esac
awk_script=$(dirname "$0")/skeleton.awk
tmp=$(mktemp) || exit 1
trap 'rm -f "$tmp"' EXIT
status=0
for solution in "$@"; do
    skeleton=chapters/${solution#solutions/}
    if ! awk -f "$awk_script" "$solution" >"$tmp"; then
        echo "$solution: cannot make its skeleton" >&2
        status=1
        continue
    fi
    if cmp -s "$tmp" "$skeleton"; then
        continue
    fi
    if [ "$mode" = check ]; then
        if [ -e "$skeleton" ]; then
            echo "$skeleton: differs from the skeleton generated from $solution (run make skeletons)" >&2
        else
            echo "$skeleton: missing; it is generated from $solution (run make skeletons)" >&2
        fi
        status=1
    else
        mkdir -p "$(dirname "$skeleton")"
        cp "$tmp" "$skeleton"
        echo "wrote $skeleton from $solution"
    fi
done
[ "$mode" = check ] && [ "$status" = 0 ] && echo "skeletons: all $# match their solutions"
exit $status
