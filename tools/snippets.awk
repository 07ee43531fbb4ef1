# snippets.awk - fill or check the code blocks of a Markdown text from the source.
#
#     awk -v mode=fill|check -f tools/snippets.awk README.md
#
# A block in the text, its markers at the start of their lines:
#
#     <!-- snippet: chapters/01_camera_rays/camera.h#camera -->
#     ```c
#     ...
#     ```
#     <!-- end snippet -->
#
# is the region of chapters/01_camera_rays/camera.h (a path from the top of
# the repository) between the lines `/* snippet: camera */` and
# `/* end snippet */`, without those lines and without the markers of any
# region nested in it.  Where the file has no such region, `camera` names a
# function: the block is its definition (from the line at the margin whose
# first name followed by `(` is it, to the `}` at the margin) with the
# comment right above it, so a function shown whole needs no markers.  Either
# way the block is shown without the EXERCISE_STUB(...) lines that
# tools/skeleton.awk adds to a stub (the text shows the stub as the student
# should read it), and with the indentation the region's lines share
# removed.  Blocks may not show solutions/: a student reads the chapters/ file.
#
# mode=fill prints the text with every block filled; mode=check prints
# nothing but one line per stale block or missing region.  Either exits 1
# when a block cannot be filled (or, checking, is stale).
BEGIN { status = 0; inside = 0 }

function problem(message) {
    printf "%s:%d: snippet %s: %s\n", FILENAME, start_line, where, message > "/dev/stderr"
    status = 1
}

# The definition of function `name` in `path` with the comment right above
# it, into lines[1..n] (without EXERCISE_STUB lines); n, or 0 when there is none.
function definition(path, name, lines,    all, m, k, start, first, n, j) {
    m = 0
    while ((getline all[m + 1] < path) > 0) m++
    close(path)
    start = 0
    for (k = 1; k <= m && !start; k++)
        if (all[k] ~ "^[A-Za-z_][^(]*[^A-Za-z0-9_(]" name "\\(" && all[k] !~ /;[ \t]*$/ && all[k] !~ /^(typedef|#)/)
            start = k
    if (!start) return 0
    first = start
    # the comment that ends right above it
    if (start > 1 && all[start - 1] ~ /\*\/[ \t]*$/) {
        for (j = start - 1; j > 1 && all[j] ~ /^ \*/; j--)
            ;
        if (all[j] ~ /^\/\*/) first = j
    }
    n = 0
    for (k = first; k <= m; k++) {
        if (all[k] ~ /^[ \t]*EXERCISE_STUB\(.*\);[ \t]*(\/\*.*\*\/)?[ \t]*$/) continue
        lines[++n] = all[k]
        if (k > start && all[k] ~ /^}/) return n
        if (k == start && all[k] ~ /}[ \t]*$/) return n # a definition on one line
    }
    return 0
}

# The region `name` of `path`, as a fenced block of language `lang`; "" and
# a problem when it cannot be read.
function region(path, name, lang,    line, depth, found, n, k, lines, indent, lead, text, rc) {
    if (path ~ /^solutions\//) {
        problem("shows " path ": show the chapters/ file, so that students never see a solution")
        return ""
    }
    depth = 0; found = 0; n = 0
    while ((rc = (getline line < path)) > 0) {
        if (!found) {
            if (line ~ "^[ \t]*/\\* snippet: " name " \\*/[ \t]*$") { found = 1; depth = 1 }
            continue
        }
        if (line ~ /^[ \t]*\/\* snippet: [^ ]+ \*\/[ \t]*$/) { depth++; continue }
        if (line ~ /^[ \t]*\/\* end snippet \*\/[ \t]*$/) {
            if (--depth == 0) break
            continue
        }
        if (line ~ /^[ \t]*EXERCISE_STUB\(.*\);[ \t]*(\/\*.*\*\/)?[ \t]*$/) continue
        lines[++n] = line
    }
    close(path)
    if (rc < 0) { problem("cannot read " path); return "" }
    if (!found) n = definition(path, name, lines)
    if (!found && n == 0) { problem("no region /* snippet: " name " */ and no function " name " in " path); return "" }
    if (depth != 0) { problem("the region " name " in " path " has no /* end snippet */"); return "" }
    indent = -1
    for (k = 1; k <= n; k++) {
        if (lines[k] ~ /^[ \t]*$/) continue
        match(lines[k], /^[ \t]*/)
        if (indent < 0 || RLENGTH < indent) indent = RLENGTH
    }
    text = "```" lang "\n"
    for (k = 1; k <= n; k++) {
        lead = lines[k]
        if (indent > 0) lead = (lead ~ /^[ \t]*$/) ? "" : substr(lead, indent + 1)
        text = text lead "\n"
    }
    return text "```\n"
}

inside == 0 && /^<!-- snippet: [^ #]+#[A-Za-z0-9_.-]+ -->[ \t]*$/ {
    where = $3
    start_line = FNR
    inside = 1
    old = ""
    if (mode == "fill") print
    next
}
inside == 1 && /^<!-- end snippet -->[ \t]*$/ {
    inside = 0
    split(where, part, "#")
    lang = "c"
    if (match(old, /^```[A-Za-z0-9_+-]*\n/)) lang = substr(old, 4, RLENGTH - 4)
    new = region(part[1], part[2], lang)
    if (new == "") new = old
    else if (new != old && mode == "check") problem("the block is stale (run make snippets)")
    if (mode == "fill") printf "%s%s\n", new, $0
    next
}
inside == 1 { old = old $0 "\n"; next }
mode == "fill" { print }

END {
    if (inside) problem("no <!-- end snippet --> after the marker")
    exit status
}
