#!/bin/bash
# take-submission.sh SUBMISSION PRISTINE [CHAPTER] - put a student's exercise files in chapters/.
#
# For each exercise file chapters/NN_name/FILE.c of the graded chapters
# (CHAPTER, 01 or 01_camera_rays; empty: all), the file first goes back to
# the skeleton kept in PRISTINE/NN_name/FILE.c, then is replaced by the
# submission's file, taken by, in this order:
#   its path, .../NN_name/FILE.c;
#   its name, FILE.c, anywhere (when no other chapter has a file of that name);
#   its name as a browser or a file manager changes it on a second upload or
#   a copy: "FILE (1).c", "FILE-1.c", "FILE_1.c", "FILE copy.c", "FILE copy 2.c".
# Only regular files are taken, and nothing but these files: a submission
# cannot replace a test, a header or common/.  A link, a folder reached
# through one, anything but a regular file, a name holding a control
# character (a newline: names are listed one a line) and a file over 1 MB
# are never taken, each said so; a file is taken only when its real path
# lies inside the submission.  Only files named *.c and links are looked at
# (every exercise file is a .c), at most 1000 in the order of their paths: each
# costs a few processes, and a submission of 100000 files would otherwise
# take minutes before the grading, outside its time budget.  Prints one line
# per file (used, renamed, or missing: the skeleton is graded) and the
# submitted files that were not used; the grader shows these lines above the
# results.  The exercise files of a chapter are those with a solution, or in
# a student's copy the members of reference/double/libNN_name.a.
set -u
submission=${1:?usage: take-submission.sh SUBMISSION PRISTINE [CHAPTER]}
pristine=${2:?}
chapter=${3:-}

exercises() { # "NN_name FILE.c" lines
    local c f
    for c in chapters/[0-9][0-9]_*/; do
        c=$(basename "$c")
        if [ -d solutions ]; then
            for f in solutions/"$c"/*.c; do [ -e "$f" ] && echo "$c $(basename "$f")"; done
        elif [ -e reference/double/lib"$c".a ]; then
            ar t reference/double/lib"$c".a | sed "s/\.o\$/.c/; s/^/$c /"
        fi
    done
}

list=$(exercises)
used=$(mktemp)
notes=$(mktemp)
trap 'rm -f "$used" "$notes"' EXIT
limit=1048576 # bytes: a larger file is not taken
real_submission=$(realpath -e "$submission" 2>/dev/null) || real_submission=/nonexistent
# shown NAME: the name with every control character as '?', for the notes.
shown() { printf '%s' "$1" | tr '\000-\037\177' '?'; }
# The submission's regular files, by path below it, one a line: names with a
# control character, links and other kinds, and large files go to the notes.
c_limit=1000
files=$(cd "$submission" 2>/dev/null && find . -mindepth 1 \( -name '*.c' -o -type l \) -print0 | sort -z |
    head -z -n $((c_limit + 1)) |
    { seen=0
    while IFS= read -r -d '' path; do
        path=${path#./}
        seen=$((seen + 1))
        if [ "$seen" -gt "$c_limit" ]; then
            echo "(more than $c_limit files named *.c or links: those after the first $c_limit were not looked at)" >>"$notes"
        elif [[ $path == *[[:cntrl:]]* ]]; then
            echo "$(shown "$path") (a name with a control character: never taken)" >>"$notes"
        elif [ -L "$path" ]; then
            echo "$path (a link: never taken)" >>"$notes"
        elif [ -d "$path" ]; then
            :
        elif [ ! -f "$path" ]; then
            echo "$path (not a regular file: never taken)" >>"$notes"
        elif [ "$(stat -c %s -- "$path")" -gt "$limit" ]; then
            echo "$path (over 1 MB: never taken)" >>"$notes"
        else
            case $(realpath -e -- "$path" 2>/dev/null) in
            "$real_submission"/*) printf '%s\n' "$path" ;;
            *) echo "$path (outside the submission: never taken)" >>"$notes" ;;
            esac
        fi
    done; })
# The other files (not *.c, not links), only named: the first 20.
others=$(cd "$submission" 2>/dev/null && find . -mindepth 1 ! -name '*.c' ! -type d ! -type l -print0 | sort -z |
    head -z -n 20 |
    while IFS= read -r -d '' path; do shown "${path#./}"; echo; done)

echo "Files taken from your submission:"
while read -r c f; do
    [ -n "$c" ] || continue
    if [ -n "$chapter" ]; then
        case "$c" in "$chapter" | "$chapter"_*) ;; *) continue ;; esac
    fi
    cp "$pristine/$c/$f" "chapters/$c/$f" || exit 1 # the skeleton, should the file be missing
    base=${f%.c}
    how=""
    found=$(printf '%s\n' "$files" |
        awk -v p="$c/$f" '$0 == p || substr($0, length($0) - length(p)) == "/" p' | head -n 1)
    if [ -z "$found" ] && [ "$(printf '%s\n' "$list" | awk -v f="$f" '$2 == f' | wc -l)" = 1 ]; then
        candidates=$(printf '%s\n' "$files" | awk -F/ -v f="$f" '$NF == f')
        found=$(printf '%s\n' "$candidates" | head -n 1)
        if [ "$(printf '%s\n' "$candidates" | grep -c .)" -gt 1 ]; then
            how=" (you uploaded $(printf '%s\n' "$candidates" | grep -c .) files named $f; this one was used)"
        fi
        if [ -z "$found" ]; then
            found=$(printf '%s\n' "$files" | awk -F/ -v b="$base" '
                { n = $NF; if (substr(n, 1, length(b)) != b) next; rest = substr(n, length(b) + 1)
                  if (rest ~ /^( \([0-9]+\)|[-_][0-9]+| copy| copy [0-9]+| - Copy)\.c$/) print }' | head -n 1)
            [ -n "$found" ] && how=" (renamed: submit it as $f)"
        fi
    fi
    if [ -n "$found" ]; then
        # a regular file, not a link, inside the submission (checked again)
        [ -f "$submission/$found" ] && [ ! -L "$submission/$found" ] || exit 1
        head -c "$limit" -- "$submission/$found" >"chapters/$c/$f" || exit 1
        echo "$found" >>"$used"
        echo "  chapters/$c/$f: your $found$how"
    else
        echo "  chapters/$c/$f: MISSING from your submission; the untouched skeleton is graded (upload $f)"
    fi
done <<<"$list"
unused=$(printf '%s\n%s\n' "$files" "$others" | grep -vxF -f "$used" | grep . | head -n 20)
[ -s "$notes" ] && unused=$(printf '%s\n%s\n' "$unused" "$(head -n 20 "$notes")" | grep .)
if [ -n "$unused" ]; then
    echo "Not used (only the graded chapter's exercise files are):"
    printf '%s\n' "$unused" | sed 's/^/  /'
fi
exit 0
