#!/bin/bash
# check-links.sh - the repository points at nothing outside itself.
#
# Fails naming the file and line of every relative Markdown link whose target
# does not exist, and of every mention of DESIGN.md or SCENES.md in a source
# or text file (.c .h .md .sh .awk .txt .xml, Makefile): those are notes
# beside the repository; its own versions are docs/design.md and
# docs/scenes.md.  Data (fuzzing corpora, images) is not searched.
set -u
status=0
files=$(git ls-files 2>/dev/null || find . -type f -not -path './build*' -not -path './out*' | sed 's|^\./||')
while IFS= read -r f; do
    case "$f" in *.md) ;; *) continue ;; esac
    [ -f "$f" ] || continue
    while IFS=: read -r line target; do
        path=${target%%#*}
        [ -z "$path" ] && continue
        case "$path" in http://* | https://* | mailto:*) continue ;; esac
        if [ ! -e "$(dirname "$f")/$path" ]; then
            echo "$f:$line: the link $target leads nowhere" >&2
            status=1
        fi
    done < <(grep -no '\](\([^)]*\))' "$f" | sed 's/^\([0-9]*\):\](\(.*\))$/\1:\2/')
done <<<"$files"
while IFS= read -r hit; do
    [ -n "$hit" ] || continue
    echo "$hit: names a file outside the repository (docs/design.md, docs/scenes.md are ours)" >&2
    status=1
done < <(printf '%s\n' "$files" | grep -v '^tools/check-links.sh$' | grep -E '\.(c|h|md|sh|awk|txt|xml)$|(^|/)Makefile$' |
    while IFS= read -r f; do
        [ -f "$f" ] && grep -HnI 'DESIGN\.md\|SCENES\.md' "$f" | cut -d: -f1,2
    done)
[ "$status" = 0 ] && echo "links: every relative link resolves; nothing names DESIGN.md or SCENES.md"
exit $status
