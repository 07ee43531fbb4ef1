#!/bin/bash
# build.sh OUT - write the book, a static site, into the folder OUT.
#
# One page per text of pages.sh (the title page, each chapter's lesson and
# lab, the measurements, the scene format, the guides), made by pandoc with
# book.lua and template.html; a listing page for every source file a page
# shows or links (src/PATH.html, numbered lines), always the file of
# chapters/ as a student has it, never solutions/; copies of the images;
# KaTeX (Debian's libjs-katex) for the equations and book.css.  Nothing is
# fetched at reading time.  The site is written beside OUT and put in its
# place only when it is complete.  Run from the top of the repository.
set -euo pipefail
out=${1:?usage: build.sh OUT}
here=$(dirname "$0")
katex=/usr/share/javascript/katex
tmp="$out.tmp-$$"
trap 'rm -rf "$tmp"' EXIT
rm -rf "$tmp"
mkdir -p "$tmp"
pages="$tmp/.pages.tsv" needs="$tmp/.needs"
"$here/pages.sh" >"$pages"
: >"$needs"

# page SOURCE PAGE TITLE PREV PREV_TITLE NEXT NEXT_TITLE
page() {
    BOOK_SOURCE=$1 BOOK_PAGES=$pages BOOK_NEEDS=$needs \
        pandoc -f gfm+tex_math_dollars -t html5 --lua-filter "$here/book.lua" --template "$here/template.html" \
        --katex=katex/ --highlight-style=tango \
        -M pagetitle="$3" -V root= ${4:+-V prev="$4" -V prev-title="$5"} ${6:+-V next="$6" -V next-title="$7"} \
        -o "$tmp/$2.html" "$1"
}

mapfile -t lines <"$pages"
for i in "${!lines[@]}"; do
    IFS=$'\t' read -r src name title <<<"${lines[$i]}"
    prev=() next=()
    [ "$i" -gt 0 ] && IFS=$'\t' read -r _ p pt <<<"${lines[$((i - 1))]}" && prev=("$p" "$pt")
    [ "$((i + 1))" -lt "${#lines[@]}" ] && IFS=$'\t' read -r _ n nt <<<"${lines[$((i + 1))]}" && next=("$n" "$nt")
    page "$src" "$name" "$title" "${prev[0]:-}" "${prev[1]:-}" "${next[0]:-}" "${next[1]:-}"
done

# The copies and listings the pages need (the listings two at a time).
sed -n 's/^copy //p' "$needs" | sort -u | while read -r path; do
    mkdir -p "$tmp/files/$(dirname "$path")" && cp "$path" "$tmp/files/$path"
done
sed -n 's/^listing //p' "$needs" | sort -u |
    xargs -P 2 -I '{}' "$here/listing.sh" '{}' "$pages" "$tmp/src/{}.html"

mkdir -p "$tmp/katex"
cp "$katex/katex.min.js" "$katex/katex.min.css" "$tmp/katex/"
cp -RL "$katex/fonts" "$tmp/katex/"
cp "$here/book.css" "$tmp/"
rm -f "$pages" "$needs"
rm -rf "$out"
mv "$tmp" "$out"
trap - EXIT
echo "wrote $out: ${#lines[@]} pages, $(find "$out/src" -name '*.html' 2>/dev/null | wc -l) listings, $(find "$out/files" -type f 2>/dev/null | wc -l) images"
