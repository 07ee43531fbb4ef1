#!/bin/sh
# snippets.sh fill|check TEXT... - the code blocks of Markdown texts, from the source.
#
# `fill` rewrites each text whose blocks are not what tools/snippets.awk
# makes of the source; `check` changes nothing and fails naming the text and
# the snippet of every stale block or missing region.
mode=$1
shift
case "$mode" in fill|check) ;; *) echo "usage: $0 fill|check TEXT..." >&2; exit 2 ;; esac
awk_script=$(dirname "$0")/snippets.awk
tmp=$(mktemp) || exit 1
trap 'rm -f "$tmp"' EXIT
status=0
blocks=0
for text in "$@"; do
    blocks=$((blocks + $(grep -c '^<!-- snippet: ' "$text")))
    if [ "$mode" = check ]; then
        awk -v mode=check -f "$awk_script" "$text" || status=1
    elif awk -v mode=fill -f "$awk_script" "$text" >"$tmp"; then
        cmp -s "$tmp" "$text" || { cp "$tmp" "$text" && echo "filled the snippets of $text"; }
    else
        status=1
    fi
done
[ "$mode" = check ] && [ "$status" = 0 ] && echo "snippets: all $blocks blocks match their source"
exit $status
