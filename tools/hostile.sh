#!/bin/bash
# hostile.sh [ZIP] - hostile submissions against chapter 05's autograder under a fake root.
#
# Sets up the Gradescope zip (ZIP, or `make autograder CHAPTER=05` built
# here) as docs/instructor-guide.md says, under a folder of /tmp standing for
# /autograder, and grades each submission of tests/hostile/ with its
# run_autograder: the forging attacks (a constructor that forges the
# per-test token, lambert finding it on the stack, definitions of cmocka's
# _fail and _cmocka_run_group_tests, a table of the suite's published inputs,
# the compiled reference re-emitted as assembly, and the same hidden from
# the check for assembly: after a #line naming a system header, under an #if
# on a flag of the compile's own, in a section attribute's name, between two
# character constants '"' (whose quotes a removal of strings first would pair
# with the assembly's), under an #if on the compile's own output file (which
# a preprocessing of the check's own had opened already), between two lone
# quotes in pragmas (which the compiler only warns of); an asm statement in a
# correct lambert, written as the C library renames a declaration; a correct
# lambert called through a static indirect function; the compiled
# reference's bytes copied into memory made executable at run time, or into
# a file mapped executable; and one
# the grader's own
# design invites: running the reference's suite to write the records), a
# symlink tree with a
# newline in a folder's name aimed at the grader's grade.conf, an #include of
# grade.conf when the grader's folder is left open to the grading user, and the
# resource attacks (memory, files left in HOME, /tmp and /run/lock, 4 GiB of 64 MiB files on disk,
# folders deeper than PATH_MAX,
# System V and POSIX IPC objects, bytes that are not
# UTF-8, characters XML does not allow (U+FFFF, in junit.xml), a test that
# never ends), escape sequences for the terminal, a line typed into the terminal the
# grading runs in (graded in one, for that), answers asked of a server
# over the network; and what outlives or outgrows a test or the compile: a
# process that stops the grader's clean-up (SIGSTOP to every process of its
# user), keys in the user's keyrings, memory in /dev/shm and in a tmpfs of a
# user namespace of its own, a NUL byte that hid the grader's notes, C1
# terminal controls in a compile error and a file's name, an assembler that
# never ends, a preprocessor that takes 9 GB, 60000 files in the submission,
# 100000 global symbols, .gnu.lto_ sections whose options make root's link
# write a file where they say, an empty section that root's link must write
# out as 6 GiB of zeros, memory in child processes and in memory files
# (memfd) and in local sockets' buffers, a test's lines that read as the grader's notes and hid them (no
# newline at the end, a right-to-left override, a character that shows as
# nothing before them), a flood of control characters from threads (the cap on
# a test's output, in results.json); besides the correct solution, a correct
# one written otherwise and an empty submission.  Prints one line per
# submission (score, expected, what was checked) and fails naming every
# expectation that does not hold (HOSTILE_ONLY="table hang" runs only
# those).  Needs root (a fake root, a user to run the
# tests as): otherwise it says so in one line and succeeds.
set -u
if [ "$(id -u)" != 0 ]; then
    echo "hostile submissions: skipped (they need root, for the fake /autograder and the grading user)"
    exit 0
fi
repo=$(pwd)
here=$repo/tests/hostile
zip=${1:-}
work=$(mktemp -d /tmp/rt-hostile-XXXXXX) || exit 1
user=rtgrade
had_user=0
id -u "$user" >/dev/null 2>&1 && had_user=1
keep=0 # the outputs are kept when an expectation does not hold
cleanup() {
    [ "$keep" = 1 ] || rm -rf "$work"
    [ "$had_user" = 1 ] || userdel "$user" >/dev/null 2>&1 || true
}
trap cleanup EXIT
export LC_ALL=C

if [ -z "$zip" ]; then
    zip=$work/autograder-05.zip
    make --no-print-directory -s autograder CHAPTER=05 TIMEOUT=3 GRADE_BUDGET=40 AUTOGRADER="$zip" >"$work/zip.log" 2>&1 ||
        { cat "$work/zip.log"; exit 1; }
fi
# The table attack: the reference's answers to every input the suite gives lambert.
make --no-print-directory -s build/hostile/record_05_lambert >"$work/record.log" 2>&1 || { cat "$work/record.log"; exit 1; }
(cd "$work" && RT_TABLE=$work/table.inc "$repo/build/hostile/record_05_lambert" >/dev/null 2>&1)
[ -s "$work/table.inc" ] || { echo "hostile: recording the suite's calls of lambert gave no table" >&2; exit 1; }

root=$work/ag
mkdir -p "$root/source" "$root/submission"
(cd "$root/source" && unzip -q "$zip") || exit 1
run_id=$(od -An -N8 -tx1 /dev/urandom | tr -d ' \n')
secret="grader-secret-$run_id"
echo "# $secret" >>"$root/source/grade.conf"
echo "setting up $zip under $root (setup.sh)"
if ! (cd "$root/source" && AUTOGRADER_ROOT=$root AUTOGRADER_NO_APT=1 bash setup.sh >"$work/setup.log" 2>&1); then
    tail -n 30 "$work/setup.log"
    echo "hostile: setup.sh failed" >&2
    exit 1
fi

# The submissions: NAME, then how to fill $root/submission.
reference_lib=$root/source/reference/double/lib05_lambert.a
make_submission() {
    local name=$1 sub=$root/submission
    rm -rf "$sub"
    mkdir -p "$sub"
    case $name in
    correct) cp "$repo/solutions/05_lambert/lambert.c" "$sub/lambert.c" ;;
    empty) ;;
    table) awk -v t="$work/table.inc" '$0 == "TABLE" { while ((getline l < t) > 0) print l; next } { print }' \
        "$here/table.c.in" >"$sub/lambert.c" ;;
    asm_reference | line_asm | ansi_asm | section_asm | quote_asm | hasinc_asm | pragma_quote_asm | pragma_quote_nop)
        (cd "$work" && rm -rf ar && mkdir ar && cd ar && ar x "$reference_lib" lambert.o) &&
            "$here/asm-from-object.sh" "$work/ar/lambert.o" >"$work/asm.c" || return 1
        case $name in
        asm_reference) cp "$work/asm.c" "$sub/lambert.c" ;;
        line_asm) { echo '#line 1 "/usr/include/stdio.h"'; cat "$work/asm.c"; } >"$sub/lambert.c" ;;
        ansi_asm) { echo '#ifdef __STRICT_ANSI__'; cat "$work/asm.c"; echo '#endif'; } >"$sub/lambert.c" ;;
        section_asm) awk -f "$here/section-from-asm.awk" "$work/asm.c" >"$sub/lambert.c" ;;
        quote_asm) { echo '#include "05_lambert/lambert.h"'
            echo "__attribute__((unused)) static const char open_quote = '\"';"
            sed '1d; s/^    "lambert:\\n"$/&\n    ".byte 0x90\\n"/' "$work/asm.c"
            echo "__attribute__((unused)) static const char close_quote = '\"';"; } >"$sub/lambert.c" ;;
        pragma_quote_asm) { echo '#include "05_lambert/lambert.h"'
            echo "#pragma hide '"
            sed '1d' "$work/asm.c"
            echo "#pragma hide '"; } >"$sub/lambert.c" ;;
        pragma_quote_nop) { echo '#include "05_lambert/lambert.h"'
            echo "_Pragma(\"hide '\")"
            sed '1d; s/^    "lambert:\\n"$/&\n    ".byte 0x90\\n"/' "$work/asm.c"
            echo "_Pragma(\"hide '\")"; } >"$sub/lambert.c" ;;
        hasinc_asm) { echo '#include "05_lambert/lambert.h"'
            echo '#if __has_include("../../out/object.o") /* the check: cc -E has opened its output already */'
            echo 'color lambert(color k_d, vec3 point, vec3 n, const scene_light *light)'
            echo '{ (void)k_d, (void)point, (void)n, (void)light; return color_make(0, 0, 0); }'
            echo '#else'
            sed '1d; s/^    "lambert:\\n"$/&\n    ".byte 0x90\\n"/' "$work/asm.c"
            echo '#endif'; } >"$sub/lambert.c" ;;
        esac ;;
    asm_statement) sed 's/^{$/{\n    if (light->intensity.r < 0) __asm__("cpuid");/' "$repo/solutions/05_lambert/lambert.c" \
        >"$sub/lambert.c" ;;
    copy)
        (cd "$work" && rm -rf ar && mkdir ar && cd ar && ar x "$reference_lib" lambert.o) &&
            "$here/bytes-from-object.sh" "$work/ar/lambert.o" >"$work/bytes.txt" || return 1
        awk -v b="$work/bytes.txt" 'BEGIN { while ((getline l < b) > 0) v[substr(l, 1, index(l, " ") - 1)] = substr(l, index(l, " ") + 1) }
            { for (k in v) if ((i = index($0, "{" k "}")) > 0) $0 = substr($0, 1, i) v[k] substr($0, i + length(k) + 1); print }' \
            "$here/copy.c.in" >"$sub/lambert.c" ;;
    escape) { cat "$here/escape.c"; printf '#warning \033[8m the compiler shows this line as it is\n'; } >"$sub/lambert.c" ;;
    local_ifunc) { sed 's/^color lambert(/static color formula(/' "$here/alternative.c"; cat "$here/local_ifunc.c.in"; } \
        >"$sub/lambert.c" ;;
    symlink)
        mkdir -p "$sub/x
05_lambert" "$sub/05_lambert"
        cp "$here/alternative.c" "$sub/x
05_lambert/lambert.c"
        ln -s "$root/source/grade.conf" "$sub/05_lambert/lambert.c" ;;
    c1_escape) # CSI (U+009B) as UTF-8, the bytes C2 9B
        sed "s/C1 CLEAR/$(printf '\302\2332J')/; s/C1 HOME/$(printf '\302\233H')/; s/C1 HIDE/$(printf '\302\2338m')/" \
            "$here/c1_escape.c.in" >"$sub/lambert.c"
        printf 'x\n' >"$sub/$(printf '\302\2332J\302\233H05_lambert 14 of 14\302\2338m').c" ;;
    many_files) # a correct lambert.c among 60000 other files (a zip of some 6 MB)
        cp "$here/alternative.c" "$sub/lambert.c"
        (cd "$sub" && mkdir junk && cd junk && seq -f 'notes-%05g.txt' 1 60000 | xargs touch) ;;
    compile_memory | many_symbols | link_memory) cat "$here/$name.c.in" "$here/alternative.c" >"$sub/lambert.c" ;;
    keyring) sed "s/\"rt-litter\"/\"rt-litter-$run_id\"/" "$here/keyring.c" >"$sub/lambert.c" ;; # a key of an earlier run may stay
    lto_root) # a correct lambert compiled with -flto on the student's machine, its options writing a file anywhere
        (cd "$repo" && gcc -O2 -flto -I common -I chapters -c "$here/alternative.c" -o "$work/lto.o" \
            -Xassembler --MD="$root/source/written-by-the-link") &&
            "$here/lto-from-object.sh" "$work/lto.o" >"$sub/lambert.c" &&
            rm -f "$root/source/written-by-the-link" ;; # (written by that compile too, on the student's machine)
    quote_quadratic) # a pragma's quote that nothing closes, then 80000 \' for QUOTES (its last line's end)
        { sed '$ s/QUOTES$//' "$here/quote_quadratic.c.in" | head -c -1; yes "\\'" | head -n 80000 | tr -d '\n'
            echo; } >"$sub/lambert.c" ;;
    readable_source) # the grader's folder left open to the grading user (an instructor grading by hand)
        printf '#include "%s/source/grade.conf"\n' "$root" >"$sub/lambert.c" ;;
    *) cp "$here/$name.c" "$sub/lambert.c" ;;
    esac
}

# NAME EXPECTED_SCORE: each case and what it must give (the score of 14 points).
cases="correct:14 alternative:14 empty:0 ctor_token:0 stack_token:0 define_fail:0 define_run_group:0 table:0
asm_reference:0 line_asm:0 ansi_asm:0 section_asm:0 local_ifunc:0 copy:0 exec_reference:0 symlink:0 memory:0 litter:0
bad_utf8:0 escape:0 tty:0 oracle:0 hang:0 quote_asm:0 hasinc_asm:0 pragma_quote_asm:0 pragma_quote_nop:0
asm_statement:0 stop_killer:0 keyring:0 nul:0 c1_escape:0 compile_hang:0 compile_memory:0 many_files:14 many_symbols:0 shm_memory:0 userns_memory:0
lto_root:0 fork_memory:0 memfd_memory:0 report_spoof:0 socket_memory:0 link_memory:0 junit_nonchar:0 disk_fill:0 readable_source:0 file_exec:0 devzero_exec:0
quote_quadratic:0 zw_spoof:0 output_flood:14"
problems=0
problem() { echo "  PROBLEM: $*"; problems=$((problems + 1)); }
printf '%-18s %6s %8s %6s  %s\n' submission score expected time notes
for c in $cases; do
    name=${c%:*} expected=${c#*:}
    [ -z "${HOSTILE_ONLY:-}" ] || [[ " $HOSTILE_ONLY " == *" $name "* ]] || continue
    make_submission "$name" || { problem "$name: could not make the submission"; continue; }
    server=""
    if [ "$name" = oracle ]; then # the network server the submission asks (as root: the test's user cannot stop it)
        python3 "$here/oracle-server.py" 40505 & server=$!
        python3 -c 'import socket, time, sys
for k in range(50):
    try:
        c = socket.create_connection(("127.0.0.1", 40505)); c.sendall(b"0x1p+0 " * 9 + b"0x1p+1 " * 3 + b"0x1p+0 " * 3 + b"\n"); sys.exit(not c.recv(99))
    except OSError: time.sleep(0.1)
sys.exit(1)' || problem "oracle: its server does not answer"
    fi
    start=$(date +%s)
    if [ "$name" = tty ]; then # in a terminal, then a shell that reads a line from it, as root's would
        rm -f "$work/keyboard" && mkfifo "$work/keyboard" && exec 7<>"$work/keyboard" # input that never ends
        script -qec "cd '$root/source' && AUTOGRADER_ROOT='$root' bash run_autograder; read -r -t 2 typed;
            echo \"after grading the terminal gave: \${typed:-nothing}\"" /dev/null <&7
        exec 7<&-
    else
        [ "$name" != readable_source ] || { chmod go+x "$work" && chmod -R go+rX "$root/source"; }
        (cd "$root/source" && AUTOGRADER_ROOT=$root bash run_autograder)
        chmod 700 "$work" && chmod -R go-rwx "$root/source"
    fi >"$work/$name.out" 2>&1
    took=$(($(date +%s) - start))
    [ -z "$server" ] || { kill "$server"; wait "$server"; } 2>/dev/null
    json=$root/results/results.json
    cp "$json" "$work/$name.json" 2>/dev/null
    score=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1], encoding="utf-8", errors="strict"))["score"])' \
        "$json" 2>"$work/$name.jsonerr") || score="invalid"
    # what the grader said first: a refusal, a failed answer, a limit
    notes=$(grep -ohE 'refused: it holds [^;]*|grade: (failed|crashed|timed out|not run)[^\\"]*|memory: got [0-9]+ MiB' \
        "$work/$name.out" "$json" 2>/dev/null | head -n 1 |
        awk '{ if (length($0) > 70) { s = substr($0, 1, 70); sub(/ [^ ]*$/, "", s); $0 = s " ..." } print }')
    [ "$score" = invalid ] && notes="results.json is not valid UTF-8 JSON: $(tail -n 1 "$work/$name.jsonerr")"
    printf '%-18s %6s %8s %6s  %s\n' "$name" "$score" "$expected" "${took}s" "$notes"
    [ "$score" = "$expected" ] || problem "$name scored $score, expected $expected"
    if grep -qF "$secret" "$work/$name.out" "$json" 2>/dev/null; then problem "$name: a line of the grader's grade.conf is in the output"; fi
    case $name in
    correct) grep -q "matches the compiled reference" "$work/$name.out" || problem "correct: not flagged as the reference's code" ;;
    alternative) grep -q "matches the compiled reference" "$work/$name.out" && problem "alternative: flagged as the reference's code" ;;
    line_asm | ansi_asm) grep -q "refused: it holds assembly" "$work/$name.out" || problem "$name: not refused as assembly" ;;
    section_asm) grep -q "refused: it holds an attribute whose text goes to the assembler" "$work/$name.out" ||
        problem "section_asm: the section attribute not refused" ;;
    local_ifunc) grep -q "refused: it holds an indirect function" "$work/$name.out" ||
        problem "local_ifunc: the static indirect function not refused" ;;
    escape) ! grep -q "$(printf '\033')" "$work/$name.out" || problem "escape: an escape sequence reached the terminal" ;;
    c1_escape) ! LC_ALL=C grep -q "$(printf '\302')[$(printf '\200-\237')]" "$work/$name.out" ||
        problem "c1_escape: a C1 control (CSI) reached the terminal: $(LC_ALL=C grep -c "$(printf '\302\233')" "$work/$name.out") lines" ;;
    tty) grep -q "after grading the terminal gave: nothing" "$work/$name.out" ||
        problem "tty: a line typed into the grading's terminal: $(grep -a 'terminal gave' "$work/$name.out")" ;;
    memory | shm_memory | userns_memory | fork_memory | memfd_memory | socket_memory)
        got=$(grep -ho 'memory: got [0-9]* MiB' "$json" | awk '{ print $3 }' | sort -n | tail -n 1)
        [ -n "$got" ] && [ "$got" -le 1024 ] || problem "memory: the test took ${got:-?} MiB (limit 1024)" ;;
    litter)
        grep -q "litter: found" "$json" && problem "litter: a test found files an earlier test left"
        left=$(find /tmp /var/tmp /dev/shm /run/lock /dev/mqueue -xdev -user "$user" 2>/dev/null | head -n 5)
        [ -z "$left" ] || problem "litter: files of $user left after grading: $left"
        ipc=$(ipcs -c 2>/dev/null | awk -v u="$user" '$3 == u || $5 == u' | head -n 3)
        [ -z "$ipc" ] || problem "litter: System V IPC of $user left after grading: $ipc" ;;
    nul) # every test's output shows why it failed, and its float build's verdict
        python3 -c 'import json, sys
t = [x for x in json.load(open(sys.argv[1]))["tests"] if x["max_score"]]
sys.exit(not all("grade: failed" in x["output"] and "float build (REAL=float)" in x["output"] for x in t))' "$json" ||
            problem "nul: a test's output in results.json lacks the grader's note" ;;
    keyring)
        grep -q "litter: found" "$json" && problem "keyring: a test found a key an earlier test left"
        left="" # the look below calls keyctl by its x86-64 number
        [ "$(uname -m)" != x86_64 ] || left=$(setpriv --reuid="$user" --regid="$(id -g "$user")" --clear-groups -- env -i PATH=/usr/bin:/bin python3 -c 'import ctypes, sys
libc = ctypes.CDLL(None, use_errno=True)
keyctl = 250  # x86_64: KEYCTL_GET_PERSISTENT 22, KEYCTL_SEARCH 10
for ring in (-4, -5, libc.syscall(keyctl, 22, -1, -4)):
    if ring != -1 and libc.syscall(keyctl, 10, ring, b"user", sys.argv[1].encode(), 0) > 0:
        print(ring)' "rt-litter-$run_id" 2>/dev/null)
        [ -z "$left" ] || problem "keyring: keys of $user left after grading (keyrings $left)" ;;
    lto_root) [ ! -e "$root/source/written-by-the-link" ] ||
        problem "lto_root: the link wrote, as root, where the submission chose: $(head -c 80 "$root/source/written-by-the-link")" ;;
    report_spoof) # every failed test's reason ends in the grader's note, on a line of its own; no bidi control shown
        failed=$(grep -c '^  FAIL  test_' "$work/$name.out")
        notes=$(grep -c '^        grade: failed' "$work/$name.out")
        [ "$notes" = "$failed" ] || problem "report_spoof: the grader's note shown for $notes of $failed failed tests"
        ! grep -q '^        grade: passed' "$work/$name.out" ||
            problem "report_spoof: the test's 'grade: passed' shown as the grader's"
        ! grep -q "$(printf '\342\200\256')" "$work/$name.out" "$json" ||
            problem "report_spoof: a bidi control in the report" ;;
    many_symbols) [ "$took" -le 60 ] || problem "many_symbols: grading took ${took}s (a budget of 40 s)"
        grep -q "refused: it holds a definition of v00000, .*, and 99995 more definitions" "$work/$name.out" ||
            problem "many_symbols: not refused as 100000 definitions" ;;
    many_files) [ "$took" -le 60 ] || problem "many_files: grading took ${took}s (a budget of 40 s)" ;;
    disk_fill)
        wrote=$(grep -ho 'disk fill: wrote [0-9]* MiB' "$json" | awk '{ print $4 }' | sort -n | tail -n 1)
        [ -n "$wrote" ] && [ "$wrote" -le 64 ] || problem "disk_fill: a test wrote ${wrote:-?} MiB of files (64 MiB files)" ;;
    junit_nonchar) python3 -c 'import sys, xml.etree.ElementTree as x; x.parse(sys.argv[1])' \
        "$root/source/build-grade/junit.xml" 2>/dev/null || problem "junit_nonchar: junit.xml is not well-formed XML" ;;
    quote_quadratic) [ "$took" -le 30 ] ||
            problem "quote_quadratic: grading took ${took}s (the check of the file, as root, outside every limit)"
        grep -q "refused: it holds an unterminated character or string literal" "$work/$name.out" ||
            problem "quote_quadratic: not refused as an unterminated literal" ;;
    zw_spoof) # no line of the test's reads as the grader's once invisible characters (Unicode format, Cf) are left out
        python3 -c 'import json, re, sys, unicodedata
seen = lambda line: "".join(c for c in line if unicodedata.category(c) != "Cf")
spoof = re.compile(r"(grade: passed|float build \(REAL=float\): passed)")
out = [l for l in open(sys.argv[1], encoding="utf-8", errors="replace").read().split("\n") if spoof.match(seen(l)[8:])
       and seen(l).startswith(" " * 8) and not seen(l).startswith(" " * 9) and not spoof.match(l[8:])]
res = [l for t in json.load(open(sys.argv[2]))["tests"] for l in t["output"].split("\n")
       if spoof.match(seen(l)) and not spoof.match(l)]
print(len(out), len(res)); sys.exit(bool(out or res))' "$work/$name.out" "$json" >"$work/$name.spoof" ||
            problem "zw_spoof: a test's line shown as the grader's (terminal, results.json):" \
                "$(cat "$work/$name.spoof")" ;;
    output_flood) size=$(stat -c %s "$json" 2>/dev/null || echo 0)
        echo "  (results.json: $size bytes, junit.xml: $(stat -c %s "$root/source/build-grade/junit.xml") bytes)"
        [ "$size" -le 2097152 ] || problem "output_flood: results.json holds $size bytes" \
            "(9 tests, 16 KiB of output a run, 6 bytes a control character: under 2 MiB)" ;;
    link_memory) [ "$took" -le 30 ] || problem "link_memory: grading took ${took}s (root's link of a 6 GiB section)" ;;
    compile_hang) [ "$took" -le 90 ] || problem "compile_hang: grading took ${took}s (a budget of 40 s)" ;;
    stop_killer) [ "$took" -le 60 ] || problem "stop_killer: grading took ${took}s (a stopped clean-up waited for?)" ;;
    hang)
        grep -q "time budget" "$work/$name.out" || problem "hang: the time budget did not stop the grading"
        [ "$took" -le 90 ] || problem "hang: grading took ${took}s" ;;
    esac
    # (a zombie that init has yet to reap runs nothing: not counted)
    running=$(ps -u "$user" -o stat=,pid=,ppid=,args= 2>/dev/null | awk '$1 !~ /^Z/' | head -n 3)
    [ -z "$running" ] || problem "$name: processes of $user still run after grading: $running"
done
if [ "$problems" -gt 0 ]; then
    echo "hostile submissions: $problems problems (outputs in $work, kept)"
    keep=1
    exit 1
fi
echo "hostile submissions: every expectation holds"
