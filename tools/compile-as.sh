#!/bin/bash
# compile-as.sh USER OBJECT SOURCE COMPILER ARGS... - compile a student's file as USER.
#
# The autograder compiles the student's files (chapters/NN_name/*.c) as the
# unprivileged user the tests run as, so that a submission's #include can
# read nothing but what every student has: the source and the project's
# headers (common/, chapters/, tests/) are copied into a fresh folder under
# /tmp that USER may read, the compiler runs there as USER (setpriv), with
# the same relative paths, so its messages read as usual, and with a time
# limit (an #include of /dev/zero would never end).  OBJECT, and the text
# it was compiled from (OBJECT's name with .i), are then copied into place by
# the caller's user.
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
# The file is preprocessed once, and compiled from that text: check-exercise.sh reads the same text
# (OBJECT's .i, beside it), so that no #if can show the check another file than the compiler (an
# __has_include of an output that one run has opened and the other not yet).
as_user() {
    (cd "$tmp" && timeout -k 5 120 setpriv --reuid="$user" --regid="$(id -g "$user")" --clear-groups --reset-env -- \
        "$@")
}
as_user "$@" -E "$source" -o out/object.i && as_user "$@" -c out/object.i -o out/object.o
status=$?
[ "$status" = 124 ] && echo "$source: the compiler took more than 120 s and was stopped" >&2
[ "$status" = 0 ] || exit "$status"
cp "$tmp/out/object.i" "${object%.o}.i" && cp "$tmp/out/object.o" "$object"
