# solution-lines.awk - the lines of solution code inside a solution file's exercises.
#
#     awk -f tools/solution-lines.awk solutions/NN_name/FILE.c
#
# Prints "FILE:N<TAB>line" for each line between the end of an EXERCISE
# comment and its STUB (tools/skeleton.awk's format), trimmed, when it is code
# long enough to be telling (16 characters or more, not a comment); N numbers
# the exercises of the file.  tools/handout.sh looks for these lines in a
# student's copy: an exercise whose lines all appear in one file has leaked.
FNR == 1 { block = 0 }
state == "copy" && /\/\* EXERCISE [A-Za-z0-9_]+:/ {
    block++
    state = ($0 ~ /\*\//) ? "solution" : "comment"
    next
}
state == "comment" { if ($0 ~ /\*\//) state = "solution"; next }
state == "solution" && /^[ \t]*\/\* STUB[ \t]*$/ { state = "stub"; next }
state == "solution" {
    line = $0
    sub(/^[ \t]+/, "", line)
    sub(/[ \t]*\/\*.*\*\/[ \t]*$/, "", line) # a comment at the end of the line
    sub(/[ \t]+$/, "", line)
    if (length(line) >= 16 && line !~ /^(\/\*|\*\/|\* |\*$|\/\/)/) printf "%s:%d\t%s\n", FILENAME, block, line
    next
}
state == "stub" && /^[ \t]*END EXERCISE \*\/[ \t]*$/ { state = "copy"; next }
state == "stub" { next }
BEGIN { state = "copy" }
