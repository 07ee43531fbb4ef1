#!/bin/bash
# handout.sh DEST DOUBLE_LIBS FLOAT_LIBS - write the repository a student receives.
#
# DEST gets the project without solutions/: Makefile, README.md (the
# repository's first paragraph, a section for the student, the copy's layout
# and the repository's sections that hold for it), common/, chapters/ (the
# skeletons), tests/ (without tests/hostile/), tools/, docs/ (without the
# instructor's guide and CONTRIBUTING.md, and without the links to them), and reference/double/ and
# reference/float/, the compiled reference of each chapter's exercise files
# (libNN_name.a from DOUBLE_LIBS and FLOAT_LIBS, which `make handout` builds).
# The Makefile of the copy finds them: grading chapter N links the student's
# chapter N with the libraries of the others.  Then every exercise's solution
# lines (tools/solution-lines.awk) are looked for in DEST: the copy is
# refused, and removed, when one exercise's lines all appear in one file.
# `handout.sh --check DIR` runs that check alone (the autograder's zip).
set -u
tools=$(dirname "$0")

# leak_check DIR: fails naming each exercise whose solution lines are all in one file of DIR.
leak_check() {
    local dir=$1 status=0 lines block files
    lines=$(awk -f "$tools/solution-lines.awk" solutions/[0-9][0-9]_*/*.c) || return 1
    for block in $(printf '%s\n' "$lines" | cut -f1 | sort -u); do
        files=""
        first=1
        while IFS= read -r line; do
            found=$(grep -rlF --exclude='*.a' -- "$line" "$dir" | sort)
            if [ "$first" = 1 ]; then files=$found; first=0; else files=$(comm -12 <(echo "$files") <(echo "$found")); fi
        done < <(printf '%s\n' "$lines" | awk -F'\t' -v b="$block" '$1 == b { print $2 }')
        if [ -n "$files" ]; then
            echo "handout: the solution of exercise ${block##*:} of ${block%:*} is in: $(echo $files)" >&2
            status=1
        fi
    done
    return $status
}

if [ "${1:-}" = --check ]; then
    leak_check "$2" && echo "$2: no solution source (checked $(awk -f "$tools/solution-lines.awk" solutions/[0-9][0-9]_*/*.c | cut -f1 | sort -u | wc -l) exercises)"
    exit
fi

dest=${1:?usage: handout.sh DEST DOUBLE_LIBS FLOAT_LIBS}
double_libs=${2:?} float_libs=${3:?}
if [ -e "$dest" ] && [ -n "$(ls -A "$dest")" ]; then
    echo "handout: $dest exists and is not empty; give a new folder" >&2
    exit 1
fi
mkdir -p "$dest/reference/double" "$dest/reference/float" || exit 1
cp -R Makefile common chapters tests tools docs "$dest/" || exit 1
rm -rf "$dest/tests/hostile" # the attacks on the autograder hold a correct chapter 05
[ -e .gitignore ] && cp .gitignore "$dest/"
cp "$double_libs"/lib*.a "$dest/reference/double/" || exit 1
cp "$float_libs"/lib*.a "$dest/reference/float/" || exit 1
# Which functions are exercises, for tools/check-exercise.sh in a copy without solutions/.
tools/check-exercise.sh --list solutions/[0-9][0-9]_*/*.c >"$dest/reference/exercise-functions.txt" || exit 1
# The copy's README.md starts with what a student does in it, before the
# repository's first section.
student_text=$(cat <<'TEXT'
## Your copy

This is a student's copy: the exercise files in `chapters/NN_name/` are skeletons for you to complete, and
the reference versions of them come compiled, in `reference/`.  Start with
[chapters/01_camera_rays/README.md](chapters/01_camera_rays/README.md), or open `book/index.html` in a
browser: the same texts as a book, with the equations typeset and the code as you have it.  From this folder:

```sh
make                  # builds your renderers into build-student/, each built-in scene into out-student/
make grade CHAPTER=01 # your points for chapter 01: each test alone, and why it failed
make REFERENCE=01     # your renderers with chapter 01 taken from the reference (out-student-ref01/)
make STUDENT=0        # the reference renderers (build/) and images (out/), to compare yours with
```

Each renderer ends with one line naming the unfinished exercises it ran (`chapter/file.c:function`;
the file's `TODO` comment says what to do): until they are done its image lacks what they compute (the
chapter's README says how it looks, under Exercises).  In a test, an unfinished exercise prints its own line.  Chapter N's
renderer uses your chapters 1 to N, so finish them in order or take the earlier ones from the reference
with `REFERENCE=`.  `make grade` always links the reference for the other chapters: your points for a
chapter depend on that chapter's files only.  `make test` runs every suite on all your files at once (it
fails until every chapter is done).  Where the text below says `make` renders into `out/`, in this copy
your images go to `out-student/` and your renderers and suites to `build-student/` (the text's
`build/tests/test_02_sphere` is your `build-student/tests/test_02_sphere`); `out/` and `build/` hold the
reference's, once `make STUDENT=0` has built them.  Every other build's folders end in `-student` too:
`make REAL=float` builds into `build-float-student/` and renders into `out-float-student/`.

TEXT
)
layout_text=$(cat <<'TEXT'
## Layout of your copy

```
Makefile             make, make test, make grade, make help
common/              the shared core: real, vec3, ray, colour, image, PNG output, options, render loop, scenes
chapters/NN_name/    one stage each: its README, your exercise files (the TODOs), its scenes
tests/               the test suites that grade your exercises, one per chapter, and those of common/
reference/           the compiled reference of every chapter's exercise files
docs/                the index of chapters, the design, the scene format, figures, measurements
tools/               the scripts and small programs behind the make targets
```
TEXT
)
# The repository's first paragraph, the student's sections, then the
# repository's sections that hold for the copy as they are.
awk -v text="$student_text" -v layout="$layout_text" '
    /^## / && !started { print text; print ""; print layout; print ""; started = 1 }
    /^## / { keep = ($0 ~ /^## (Next to the repository|Precision and the other knobs)/) }
    !started || keep { print }' README.md >"$dest/README.md" || exit 1
# The instructor's and the maintainer's texts stay in the repository, and so
# do the links to them.
rm -f "$dest/docs/instructor-guide.md" "$dest/docs/CONTRIBUTING.md"
for f in "$dest"/docs/*.md; do
    awk '/^- \[[^]]*\]\((instructor-guide|CONTRIBUTING)\.md\)/ { skip = 1; next }
         skip && /^  / { next } { skip = 0; print }' "$f" |
        sed -E 's/ \(\[(instructor-guide|CONTRIBUTING)\.md\]\([^)]*\)\)//g' >"$f.tmp" && mv "$f.tmp" "$f" || exit 1
done
cat >"$dest/reference/README.md" <<'TEXT'
# The compiled reference

`double/libNN_name.a` and `float/libNN_name.a` hold the reference versions of chapter NN's exercise files,
compiled (for `REAL=double` and `REAL=float`).  `make grade CHAPTER=NN` grades your chapter NN with these
libraries standing in for the other chapters, so a mistake in one chapter costs points in that chapter
only.  `make STUDENT=0` builds every renderer from them: the reference images, to compare with yours.
`exercise-functions.txt` names the functions you write, file by file.
TEXT
if ! leak_check "$dest"; then
    rm -rf "$dest"
    echo "handout: refused; $dest removed" >&2
    exit 1
fi
n=$(ls "$dest"/reference/double/*.a | wc -l)
echo "wrote $dest: the student's copy (skeletons, tests, common/, docs/, and $n compiled reference libraries; no solutions/)"
