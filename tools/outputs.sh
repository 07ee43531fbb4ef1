#!/bin/sh
# outputs.sh fill|check BUILD TEXT... - the example outputs of Markdown texts, from the programs.
#
# A text shows what a command prints as
#
#     <!-- output: build/11_grid/lab -j1 -s 128x128 -o build/lab.png -->
#     ```
#     ...what it printed (stdout and stderr)...
#     ```
#     <!-- end output -->
#
# The command runs from the top of the repository, every word's leading
# build/ replaced by BUILD/.  `fill` rewrites the blocks with what the commands
# print; `check` fails naming the text and the command of every block that
# differs.  Timings change from run to run, so a number followed by " s"
# (seconds) is compared as "N s": the words and every other number must match.
mode=$1
build=$2
shift 2
case "$mode" in fill|check) ;; *) echo "usage: $0 fill|check BUILD TEXT..." >&2; exit 2 ;; esac
tmp=$(mktemp) || exit 1
trap 'rm -f "$tmp" "$tmp.a" "$tmp.b"' EXIT
mask() { sed -E 's/\b[0-9]+(\.[0-9]+)? s\b/N s/g' "$1"; }
status=0
blocks=0
for text in "$@"; do
    n=$(grep -c '^<!-- output: .* -->$' "$text")
    [ "$n" = 0 ] && continue
    blocks=$((blocks + n))
    # The text with every block filled from its command; a command that fails stops the text.
    if ! awk -v build="$build" -v text="$text" '
        /^<!-- output: .* -->$/ {
            print
            cmd = $0
            sub(/^<!-- output: /, "", cmd)
            sub(/ -->$/, "", cmd)
            run = cmd
            sub(/^build\//, build "/", run)
            gsub(/ build\//, " " build "/", run)
            print "```"
            while (((run " 2>&1; echo \"exit status $?\"") | getline line) > 0) {
                if (line ~ /^exit status /) { if (line != "exit status 0") { printf "%s: `%s` failed (%s)\n", text, cmd, line > "/dev/stderr"; bad = 1 } }
                else print line
            }
            close(run " 2>&1; echo \"exit status $?\"")
            print "```"
            skip = 1
            next
        }
        skip && /^<!-- end output -->$/ { skip = 0 }
        !skip { print }
        END { if (skip) { printf "%s: an output block without <!-- end output -->\n", text > "/dev/stderr"; exit 1 } exit bad }
    ' "$text" >"$tmp"; then
        status=1
        continue
    fi
    mask "$tmp" >"$tmp.a"
    mask "$text" >"$tmp.b"
    if cmp -s "$tmp.a" "$tmp.b"; then
        continue
    elif [ "$mode" = check ]; then
        echo "$text: an example output is not what its command prints (run make outputs):" >&2
        diff "$tmp.b" "$tmp.a" | sed -n 's/^[<>] /    /p' | head -6 >&2
        status=1
    else
        cp "$tmp" "$text" && echo "filled the outputs of $text"
    fi
done
[ "$mode" = check ] && [ "$status" = 0 ] && echo "outputs: all $blocks example outputs are what their commands print"
exit $status
