# skeleton.awk - make a student's skeleton from a solution file.
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
# solution's code, and puts the STUB lines in its place as live code.
# Everything outside exercises is copied unchanged.
BEGIN { state = "copy" }

state == "copy" && /\/\* EXERCISE [A-Za-z0-9_]+:/ {
    sub(/\/\* EXERCISE /, "/* TODO ")
    print
    state = ($0 ~ /\*\//) ? "solution" : "comment"
    next
}
state == "comment" {
    print
    if ($0 ~ /\*\//) state = "solution"
    next
}
state == "solution" && /^[ \t]*\/\* STUB[ \t]*$/ { state = "stub"; next }
state == "solution" { next }
state == "stub" && /^[ \t]*END EXERCISE \*\/[ \t]*$/ { state = "copy"; next }
state == "stub" { print; next }
{ print }

END {
    if (state != "copy") {
        printf "%s: an EXERCISE is not closed by a STUB and END EXERCISE */ (state %s)\n", FILENAME, state > "/dev/stderr"
        exit 1
    }
}
