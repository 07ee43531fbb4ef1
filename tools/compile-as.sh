#!/bin/bash
# compile-as.sh USER OBJECT SOURCE COMPILER ARGS... - compile a student's file as USER.
#
# The autograder compiles the student's files (chapters/NN_name/*.c) as the
# unprivileged user the tests run as, so that a submission's #include can
# read nothing but what every student has: the source and the project's
# headers (common/, chapters/, tests/) are copied into a fresh folder under
# /tmp that USER may read, the compiler runs there as USER (setpriv), with
# the same relative paths, so its messages read as usual, and with limits:
# 120 s for the whole compile, or what is left of the grading's time budget
# when that is less (GRADE_DEADLINE, seconds since the epoch, set by `make
# grade`: an #include of /dev/zero would never end, nor a macro of the
# assembler that calls itself twice, 40 deep), and those of a test's run
# (tools/grade.c) on memory (GRADE_MEMORY, 1024 MB: an #if on a macro that doubles 27
# times holds 9 GB) and on the size of a file (64 MB: the preprocessed text
# a file makes).  OBJECT, and the text and the assembly it was made from
# (OBJECT's name with .i and .s), are then copied into place by the
# caller's user.
set -u
user=${1:?usage: compile-as.sh USER OBJECT SOURCE COMPILER ARGS...}
object=${2:?} source=${3:?}
shift 3
tmp=$(mktemp -d /tmp/rt-compile-XXXXXX) || exit 1
trap 'rm -rf "$tmp"' EXIT
find common chapters tests -name '*.h' -exec cp --parents {} "$tmp/" \; || exit 1
cp --parents "$source" "$tmp/" || exit 1
mkdir "$tmp/out" && chown "$user" "$tmp/out" || exit 1
chmod -R a+rX "$tmp" || exit 1
# The file is preprocessed once, compiled from that text into assembly, and assembled: check-exercise.sh
# reads the same text and the same assembly (OBJECT's .i and .s, beside it), so that no #if can show the
# check another file than the compiler (an __has_include of an output that one run has opened and the
# other not yet), and an asm statement shows in the assembly (#APP) however the source hides it.
limit=120
start=$(date +%s)
if [ -n "${GRADE_DEADLINE:-}" ] && [ $((GRADE_DEADLINE - start)) -lt "$limit" ]; then
    limit=$((GRADE_DEADLINE - start))
fi
end=$((start + limit))
as_user() {
    local left=$((end - $(date +%s)))
    [ "$left" -gt 0 ] || return 124
    (cd "$tmp" && ulimit -v $((${GRADE_MEMORY:-1024} * 1024)) -f $((64 * 1024)) &&
        timeout -k 5 "$left" setpriv --reuid="$user" --regid="$(id -g "$user")" --clear-groups --reset-env -- "$@")
}
as_user "$@" -E "$source" -o out/object.i && as_user "$@" -S out/object.i -o out/object.s &&
    as_user "$@" -c out/object.s -o out/object.o
status=$?
if [ "$status" = 124 ]; then
    if [ "$limit" -lt 120 ]; then
        echo "$source: the compiler was stopped: the grading's time budget was used up" >&2
    else
        echo "$source: the compiler took more than 120 s and was stopped" >&2
    fi
fi
[ "$status" = 0 ] || exit "$status"
cp "$tmp/out/object.i" "${object%.o}.i" && cp "$tmp/out/object.s" "${object%.o}.s" && cp "$tmp/out/object.o" "$object"
