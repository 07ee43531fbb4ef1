#!/bin/bash
# check-exercise.sh REFERENCE SOURCE_DIR OBJECT_DIR FILE.c... - what a student's exercise objects may hold.
#
# Before a graded suite links a student's exercise files (chapters/NN_name/
# FILE.c, compiled into OBJECT_DIR/FILE.o), each object may define only the
# functions the reference's object of that file defines (REFERENCE: a
# folder of objects, or a library reference/REAL/libNN_name.a, member
# FILE.o), and static helpers; nothing else:
#   - no other global symbol (a definition of cmocka's _fail, of a libc or
#     project function, a global variable), and no indirect function (ifunc,
#     whose resolver would run before main);
#   - no constructor or destructor (.init_array, .fini_array, .ctors,
#     .dtors, .preinit_array, .init, .fini sections);
#   - no assembly (asm, __asm__ after preprocessing, which also rules out
#     .incbin) in the file as its compile saw it (with COMPILE_AS, the very
#     text the object was compiled from, tools/compile-as.sh, and no #APP in
#     the assembly the compiler made of it; else the file preprocessed again,
#     $CC $CPPFLAGS, all the compile's flags), no unterminated character or
#     string literal (which would hide what follows from the check); nor any text
#     the compiler hands the assembler as it is, which would be assembly all
#     the same: the attributes that name a section or a symbol (section,
#     alias, weakref, ifunc, symver, target_clones; a newline in a section's
#     name starts a line of assembly) and #ident;
#   - no code outside .text (a section both writable and executable) and no
#     executable stack (a nested function whose address is taken), where
#     bytes written as data would run.
# A refusal is one line on stdout naming the file and what was found, and
# the exit status is 1.  An exercise function whose instructions are the
# reference's, one for one, is flagged on stdout ("matches the compiled
# reference"; it is graded as usual: the instructor decides).  The flag is for
# the reference compiled from its own source (a copy of solutions/), so it
# compares only:
#   - exercise functions: those whose body holds an exercise's comment
#     ("EXERCISE name:" of the solution, "TODO name:" of the skeleton), or
#     calls a static function that does (the compiler inlines it), in
#     solutions/NN_name/FILE.c when there is one (the instructor's copy),
#     else as reference/exercise-functions.txt lists them (a student's copy
#     and the autograder: tools/handout.sh writes it from solutions/, so a
#     submission without its TODO comments is compared all the same), else
#     in the student's file; the given code of an exercise file (chapter
#     10's interpolate_uv) compiles the same for everyone;
#   - of at least MIN_INSTRUCTIONS (40) instructions in the reference: a
#     shorter one is a formula of a line or two, which correct solutions
#     written otherwise compile to the same code (two of four ways of writing
#     interpolate_vec3's one line give the reference's 30 instructions).
#   - of at most twice the reference's bytes: a longer one cannot match, and
#     objdump takes a time that grows as the square of a function's length.
#
# check-exercise.sh --list FILE.c... prints "NN_name/FILE.c function" for
# each exercise function of the solution files given (what handout.sh keeps).
set -u
# Bytes, as the compiler reads them: a multibyte locale's regular expressions skip no invalid byte, so a
# literal holding one would not match, and every quote after it would be tried to the end of its line.
export LC_ALL=C
MIN_INSTRUCTIONS=40
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
status=0

# reference_object FILE.o: the reference's object of that file, in $tmp.
reference_object() {
    if [ -d "$reference" ]; then
        echo "$reference/$1"
    else
        (cd "$tmp" && ar p "$reference" "$1" >"ref-$1") && echo "$tmp/ref-$1"
    fi
}
# exercise_functions FILE.c: the global functions of the file that hold an
# exercise's comment or call (through static functions) a static function
# that does, one a line.  A
# definition starts at a line that begins with neither a blank, a comment
# nor a preprocessor line, names a function (NAME() and does not end in ";";
# it ends at a "}" that begins a line.
exercise_functions() {
    awk '
        function name_of(line) {
            sub(/\(.*/, "", line)
            n = split(line, w, /[^A-Za-z0-9_]+/)
            return w[n] != "" ? w[n] : w[n - 1]
        }
        /^[A-Za-z_]/ && /[A-Za-z0-9_] *\(/ && !/; *$/ && !/^(typedef|struct|enum|union)[^A-Za-z0-9_]/ {
            f = name_of($0); static_[f] = $0 ~ /^static[^A-Za-z0-9_]/; body[f] = ""; order[++count] = f
        }
        f != "" { body[f] = body[f] " " $0 }
        f != "" && /\/\* *(EXERCISE|TODO) [A-Za-z0-9_ -]+:/ { marked[f] = 1 }
        /^}/ { f = "" }
        END { # marked too: what calls a marked static function, through any number of static calls
            do {
                changed = 0
                for (k = 1; k <= count; k++) {
                    g = order[k]
                    for (h in marked)
                        if (!marked[g] && static_[h] && match(body[g], "(^|[^A-Za-z0-9_])" h " *\\(")) {
                            marked[g] = 1
                            changed = 1
                        }
                }
            } while (changed)
            for (k = 1; k <= count; k++)
                if (marked[order[k]] && !static_[order[k]]) print order[k]
        }' "$1" | sort -u
}
if [ "${1:-}" = --list ]; then
    shift
    for file in "$@"; do
        exercise_functions "$file" | sed "s|^|$(basename "$(dirname "$file")")/$(basename "$file") |"
    done
    exit 0
fi
reference=${1:?usage: check-exercise.sh REFERENCE SOURCE_DIR OBJECT_DIR FILE.c...}
sources=${2:?} objects=${3:?}
case $reference in /*) ;; *) reference=$(pwd)/$reference ;; esac
shift 3
# In a student's copy, the exercise functions as handout.sh listed them from solutions/.
listed=$(dirname "$(dirname "$reference")")/exercise-functions.txt
# The size in bytes of function $2 in object $1 (0 when it has none).
symbol_size() {
    local hex
    hex=$(nm -S --defined-only "$1" 2>/dev/null | awk -v f="$2" '$4 == f && NF == 4 { print $2; exit }')
    echo $((16#${hex:-0}))
}
# The instructions of function $2 in object $1, without addresses, bytes or relocation targets.
instructions() {
    objdump -d --no-show-raw-insn --disassemble="$2" "$1" 2>/dev/null |
        awk -F'\t' '/^ *[0-9a-f]+:\t/ { sub(/ *[#<].*/, "", $2); print $2 }'
}

# preprocess SOURCE OBJECT OUT: SOURCE as its compile saw it.  Compiled as
# the user COMPILE_AS (tools/compile-as.sh), the text the object was compiled
# from, which compile-as.sh keeps beside it (OBJECT's name with .i): the
# check reads what the compiler read, so that no #if (__has_include,
# __STRICT_ANSI__, _OPENMP, an output file one run has opened and another not
# yet) can show it another file.  Otherwise (a student's own `make grade`,
# not sealed against the student), SOURCE preprocessed again with the same
# flags ($CPPFLAGS: all of the compile's).
preprocess() {
    if [ -n "${COMPILE_AS:-}" ]; then
        [ -f "${2%.o}.i" ] && cp "${2%.o}.i" "$3"
    else
        timeout -k 5 60 ${CC:-cc} ${CPPFLAGS:-} -E "$1" -o "$3" >/dev/null 2>&1
    fi
}

for file in "$@"; do
    src=$sources/$file obj=$objects/${file%.c}.o
    ref=$(reference_object "${file%.c}.o") || { echo "$src: no reference object to check it against" >&2; exit 1; }
    allowed=$(nm -g --defined-only "$ref" | awk '{ print $3 }' | sort -u)
    # In one pass (an object may define 100000 symbols, in plain C): the first five named, the rest counted.
    problems=$(nm -g --defined-only "$obj" | awk -v allowed="$allowed" '
        BEGIN { n = split(allowed, a, "\n"); for (k = 1; k <= n; k++) ok[a[k]] = 1 }
        NF < 3 { next }
        { if ($2 == "i") what = "an indirect function " $3 " (its resolver runs before main)"
          else if (!($3 in ok)) what = "a definition of " $3
          else next
          if (++count <= 5) printf ", %s", what }
        END { if (count > 5) printf ", and %d more definitions", count - 5 }')
    # a static one too (nm -g lists only the global)
    [[ $problems == *"indirect function"* ]] || nm --defined-only "$obj" | awk '$2 == "i" { exit 1 }' ||
        problems="$problems, an indirect function (its resolver runs before main)"
    sections=$(objdump -h "$obj" | awk '$2 ~ /^\.(init_array|fini_array|preinit_array|ctors|dtors|init|fini)($|\.)/ { print $2 }' | sort -u | tr '\n' ' ')
    [ -n "$sections" ] && problems="$problems, a constructor or destructor (section ${sections% })"
    # Where bytes written as data could run: code outside .text, an executable stack.
    problems="$problems$(objdump -h "$obj" | awk '
        /^ *[0-9]+ / { name = $2; getline; flags = $0
            if (name == ".note.GNU-stack") { marked = 1; if (flags ~ /CODE/) stack = 1 }
            else if (flags ~ /ALLOC/ && flags ~ /CODE/ && (name !~ /^\.text($|\.)/ || flags !~ /READONLY/)) code = code " " name }
        END { if (code != "") printf ", code outside .text (section%s)", code
              if (stack || !marked) printf ", an executable stack (a nested function whose address is taken)" }')"
    # Assembly, after preprocessing: the identifiers asm, __asm, __asm__ in
    # any line of the file as the compiler saw it (what it includes too: a
    # #line or a system_header pragma would make the file's own lines look
    # like a header's), outside strings and characters (both removed in one
    # pass from left to right, so that a '"' cannot pair with a string's
    # quote), but for the renaming of a declaration (the C library's
    # `) __asm__ ("" "name")`, no code);
    # and what hands the assembler a text as it is.  The file compiled, so what it
    # includes is there.
    # Compiled as COMPILE_AS: an asm statement or block, however the source hides it, is in the
    # assembly the compiler made (GCC marks each #APP); a C library's renaming is not.
    if [ -n "${COMPILE_AS:-}" ]; then
        if [ ! -f "${obj%.o}.s" ]; then
            problems="$problems, no assembly of its compile to check (tools/compile-as.sh keeps it)"
        elif grep -q '^[[:space:]]*#APP' "${obj%.o}.s"; then
            problems="$problems, assembly (asm)"
        fi
    fi
    if ! preprocess "$src" "$obj" "$tmp/pre.c"; then
        problems="$problems, something the preprocessor cannot read again"
    else
        grep -v '^# [0-9]' "$tmp/pre.c" >"$tmp/lines.c"
        # In preprocessed text every literal lies on one line: a quote left on a line once its strings
        # and characters are removed opens none (a lone ' in a #pragma, which the compiler only warns
        # of), and would pair with a quote lines away in the joined text below, hiding what lies between.
        # Found first, by grep's automaton in one pass: a line where some quote opens no literal that closes
        # on it.  The removals below, a regular expression's leftmost match at every position, try each
        # quote after one that nothing closes up to the end of the line: 40000 \' after a lone ' in a
        # pragma took 15 s, 1 MB of them hours, as root and outside every limit.  So they read only text
        # whose literals all close, where no try fails.
        if grep -qvxE '([^"'\'']|"([^"\\]|\\.)*"|'\''([^'\''\\]|\\.)*'\'')*' "$tmp/lines.c"; then
            problems="$problems, an unterminated character or string literal (what follows it would be hidden)"
            printf '' >"$tmp/lines.c"
        fi
        sed -E 's/"([^"\\]|\\.)*"|'\''([^'\''\\]|\\.)*'\''//g' "$tmp/lines.c" | grep -q "['\"]" &&
            problems="$problems, an unterminated character or string literal (what follows it would be hidden)"
        tr '\n' ' ' <"$tmp/lines.c" |
            sed -E 's/([])A-Za-z0-9_][[:space:]]*)(__asm__|__asm|asm)[[:space:]]*\(([[:space:]]*"[A-Za-z0-9_.@]*")+[[:space:]]*\)/\1/g
                    s/"([^"\\]|\\.)*"|'\''([^'\''\\]|\\.)*'\''//g' >"$tmp/code"
        [[ $problems == *"assembly (asm)"* ]] || ! grep -qE '(^|[^A-Za-z0-9_])(__)?asm(__)?($|[^A-Za-z0-9_])' \
            "$tmp/code" || problems="$problems, assembly (asm)"
        attributes=$(grep -oE '(^|[^A-Za-z0-9_])(__)?(section|alias|weakref|ifunc|symver|target_clones)(__)?[[:space:]]*\(' \
            "$tmp/code" | tr -cd 'a-z_\n' | sed 's/^_*//; s/_*$//' | sort -u | tr '\n' ' ')
        [ -n "$attributes" ] &&
            problems="$problems, an attribute whose text goes to the assembler (${attributes% }: assembly all the same)"
        grep -qE '^[[:space:]]*#[[:space:]]*(ident|sccs|pragma[[:space:]]+(ident|sccs))([^A-Za-z0-9_]|$)' "$tmp/lines.c" &&
            problems="$problems, #ident (its text goes to the assembler: assembly all the same)"
    fi
    if [ -n "$problems" ]; then
        echo "$src: refused: it holds ${problems#, }; an exercise file may define only $(echo $allowed | sed 's/ /, /g') (helpers static), in C"
        status=1
        continue
    fi
    marked=solutions/${sources##*/}/$file
    if [ -f "$marked" ]; then
        exercise=$(exercise_functions "$marked")
    elif [ -f "$listed" ]; then
        exercise=$(awk -v f="${sources##*/}/$file" '$1 == f { print $2 }' "$listed")
    else
        exercise=$(exercise_functions "$src")
    fi
    for f in $(printf '%s\n' "$exercise" | grep -xF -- "$allowed"); do
        theirs=$(instructions "$ref" "$f")
        [ "$(printf '%s\n' "$theirs" | grep -c .)" -ge "$MIN_INSTRUCTIONS" ] || continue
        # Not disassembled when more than twice the reference's bytes (it cannot match): objdump's time grows
        # as the square of a function's length (50000 lines of plain C, one constant each: 15 s, as root).
        [ "$(symbol_size "$obj" "$f")" -le $((2 * $(symbol_size "$ref" "$f"))) ] || continue
        mine=$(instructions "$obj" "$f")
        if [ -n "$mine" ] && [ "$mine" = "$theirs" ]; then
            echo "$src: $f matches the compiled reference instruction for instruction (flagged for the instructor; graded as usual)"
        fi
    done
done
exit $status
