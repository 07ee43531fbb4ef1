#!/bin/bash
# listing.sh PATH PAGES OUT - the listing page of the repository's file PATH
# (from the top of the repository) at OUT: the file with numbered lines, each
# line's anchor L-N, under a link to the page of the file's chapter (PAGES is
# pages.sh's list).  An exercise file shows as the student receives it: the
# file of chapters/, its exercises as TODOs.
set -euo pipefail
path=$1 pages=$2 out=$3
here=$(dirname "$0")
case "$path" in
    *.c | *.h) lang=c ;;
    *.sh) lang=bash ;;
    *.awk) lang=awk ;;
    *.gp) lang=gnuplot ;;
    *.xml) lang=xml ;;
    *.md) lang=markdown ;;
    *.lua) lang=lua ;;
    *.mk | Makefile | */Makefile) lang=makefile ;;
    *) lang="" ;;
esac
# The page of the nearest folder above the file that has one, else the title page.
up=index up_title=$(awk -F'\t' '$2 == "index" { print $3 }' "$pages")
dir=$path
while [ "$dir" != . ] && [ "$dir" != / ]; do
    dir=$(dirname "$dir")
    hit=$(awk -F'\t' -v s="$dir/README.md" '$1 == s { print $2 "\t" $3 }' "$pages")
    if [ -n "$hit" ]; then
        IFS=$'\t' read -r up up_title <<<"$hit"
        break
    fi
done
# From OUT's folder back to the top of the book.
root=$(printf '%s' "src/$path" | sed 's|[^/]*/|../|g; s|[^/]*$||')
# A fence longer than any run of backticks in the file.
longest=$(grep -o '`*' "$path" | awk '{ if (length($0) > n) n = length($0) } END { print n + 0 }')
fence=$(printf '%*s' $((longest < 3 ? 3 : longest + 1)) '' | tr ' ' '`')
mkdir -p "$(dirname "$out")"
{
    printf '# `%s`\n\n' "$path"
    if grep -q 'TODO ' "$path" && grep -q 'EXERCISE_STUB' "$path"; then
        printf 'The file as a student receives it: its exercises are the `TODO` comments, each with a stub in\nplace of the solution.\n\n'
    fi
    printf '%s{#L .numberLines%s}\n' "$fence" "${lang:+ .$lang}"
    cat "$path"
    printf '%s\n' "$fence"
} | pandoc -f markdown -t html5 --template "$here/template.html" --highlight-style=tango \
    -M pagetitle="$path" -V root="$root" -V listing-of="$root$up.html" -V listing-of-title="$up_title" -o "$out"
