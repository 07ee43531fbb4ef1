#!/bin/sh
# pages.sh - the pages of the book, in reading order: one line each,
#
#     SOURCE<TAB>PAGE<TAB>TITLE
#
# SOURCE is a Markdown text of the repository, PAGE the name of its page in
# the book (PAGE.html) and TITLE its first heading.  The title page is
# docs/README.md; then each chapter's lesson, followed by its lab when the
# chapter has one (chapters/NN_name/lab/README.md, then its other pages); then the measurements, the
# scene format, the instructor's guide and the rest of docs/.  Run from the
# top of the repository.
title() { # the text of the first level-1 heading of $1
    sed -n 's/^# \(.*\)$/\1/p' "$1" | head -n 1
}
page() { # source, page
    [ -f "$1" ] || return 0
    printf '%s\t%s\t%s\n' "$1" "$2" "$(title "$1")"
}
page docs/README.md index
for dir in chapters/[0-9][0-9]_*/; do
    dir=${dir%/}
    name=$(basename "$dir")
    page "$dir/README.md" "$name"
    page "$dir/lab/README.md" "$name-lab"
    for extra in "$dir"/lab/*.md; do # the lab's further pages, after its README
        [ "$(basename "$extra")" = README.md ] || page "$extra" "$name-lab-$(basename "$extra" .md)"
    done
done
page docs/measurements.md measurements
page docs/scenes.md scenes
page docs/instructor-guide.md instructor-guide
page docs/design.md design
page docs/CONTRIBUTING.md contributing
page docs/fuzzing.md fuzzing
page README.md repository
