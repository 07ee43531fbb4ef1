# skeleton.awk - make a student's skeleton from a solution file.
#
#     awk -f tools/skeleton.awk solutions/NN_name/FILE.c > chapters/NN_name/FILE.c
#
# In a solution, an exercise is marked like this:
#
#     /* EXERCISE name: what to implement, and the lecture's equation
#      *     more lines of explanation */
#     ...the solution's code...
#     /* STUB
#     ...code that compiles and gives a wrong but harmless result...
#     END EXERCISE */
#
# The skeleton keeps the EXERCISE comment (as "TODO name: ..."), drops the
# solution's code, and puts the STUB lines in its place as live code, after
# a line EXERCISE_STUB("NN_name", "FILE.c", "name"); /* delete ... */
# (common/exercise.h), which says once on stderr that the exercise is still
# to do; its comment tells the student to delete the line with the stub.  A file that
# has exercises also gets #include "exercise.h" after its first #include.
# Everything outside exercises is copied unchanged.
BEGIN {
    state = "copy"; n = 0; exercises = 0; name = ""
    notice = "/* delete this line when done */"
}

# Keeps the skeleton's lines until the end, to add the #include.
function out(line) { lines[++n] = line }

FNR == 1 {
    k = split(FILENAME, part, "/")
    file = part[k]
    chapter = k > 1 ? part[k - 1] : "?"
}

state == "copy" && /\/\* EXERCISE [A-Za-z0-9_]+:/ {
    name = $0
    sub(/.*\/\* EXERCISE /, "", name)
    sub(/:.*/, "", name)
    sub(/\/\* EXERCISE /, "/* TODO ")
    out($0)
    state = ($0 ~ /\*\//) ? "solution" : "comment"
    exercises++
    next
}
state == "comment" {
    out($0)
    if ($0 ~ /\*\//) state = "solution"
    next
}
state == "solution" && /^[ \t]*\/\* STUB[ \t]*$/ {
    match($0, /^[ \t]*/)
    out(substr($0, 1, RLENGTH) "EXERCISE_STUB(\"" chapter "\", \"" file "\", \"" name "\"); " notice)
    state = "stub"
    next
}
state == "solution" { next }
state == "stub" && /^[ \t]*END EXERCISE \*\/[ \t]*$/ { state = "copy"; next }
state == "stub" { out($0); next }
{ out($0) }

END {
    if (state != "copy") {
        printf "%s: an EXERCISE is not closed by a STUB and END EXERCISE */ (state %s)\n", FILENAME, state > "/dev/stderr"
        exit 1
    }
    included = exercises == 0
    for (k = 1; k <= n; k++) {
        print lines[k]
        if (!included && lines[k] ~ /^#include /) {
            print "#include \"exercise.h\""
            included = 1
        }
    }
    if (!included) {
        printf "%s: has exercises but no #include line to put #include \"exercise.h\" after\n", FILENAME > "/dev/stderr"
        exit 1
    }
}
