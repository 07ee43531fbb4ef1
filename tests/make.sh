#!/bin/bash
# make.sh - checks of the build's own behaviour (make test-make, part of make test):
# what `make` prints, where it puts images, which packages it needs, and what
# a student's copy says about itself, what its renderers say.  Each check
# prints one line; the script fails when any check fails.  CC is the compiler
# of the calling build, BUILD its folder (the renderers of chapters 04, 07 and 11).
set -u
cd "$(dirname "$0")/.." || exit 1
# The makes run here are of their own, not jobs of a calling make's -j.
unset MAKEFLAGS MFLAGS MAKELEVEL
cc=${CC:-cc}
build=${BUILD:-build} # whose renderers are run
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
failed=0
count=0

# check NAME COMMAND...: runs the command, which prints why it fails.
check() {
    local name=$1
    shift
    count=$((count + 1))
    if "$@" >"$tmp/why" 2>&1; then
        echo "  ok      $name"
    else
        echo "  FAIL    $name:"
        sed 's/^/          /' "$tmp/why"
        failed=$((failed + 1))
    fi
}

# Each build variant renders the built-in scenes into its own folder.
image_folders() {
    local args want got
    while IFS='|' read -r args want; do
        # shellcheck disable=SC2086
        got=$(make -n -B --no-print-directory CC="$cc" $args all 2>&1 | grep -o ' -o [^ ]*/01_camera_rays\.png' | sort -u)
        if [ "$got" != " -o $want/01_camera_rays.png" ]; then
            echo "make $args renders chapter 01 with '${got# -o }', not into $want/"
            return 1
        fi
    done <<'LIST'
REAL=double STUDENT=0|out
REAL=float STUDENT=0|out-float
REAL=double STUDENT=1|out-student
REAL=float STUDENT=1 REFERENCE=01|out-float-student-ref01
LIST
}

# Building needs no gnuplot; the plotted figures do.  A PATH of the commands
# tools/deps.sh uses, without gnuplot.
no_gnuplot_for_building() {
    mkdir -p "$tmp/bin"
    local c
    for c in sh "$cc" timeout id mktemp rm dpkg cat; do
        ln -sf "$(command -v "$c")" "$tmp/bin/$c" || return 1
    done
    if ! PATH=$tmp/bin DEPS_NO_INSTALL=1 tools/deps.sh "$cc"; then
        echo "tools/deps.sh $cc asks for more than the build needs (gnuplot is not on its PATH)"
        return 1
    fi
    if PATH=$tmp/bin DEPS_NO_INSTALL=1 tools/deps.sh "$cc" figures 2>"$tmp/deps"; then
        echo "tools/deps.sh $cc figures does not ask for gnuplot-nox when gnuplot is missing"
        return 1
    fi
    grep -q 'gnuplot-nox' "$tmp/deps" || { echo "not named: $(cat "$tmp/deps")"; return 1; }
}

# A program built prints one line by default, its commands with V=1.
quiet_build() {
    local b=$tmp/build-quiet out
    out=$(make --no-print-directory CC="$cc" BUILD="$b" "$b/tests/test_common_vec" 2>&1)
    if [ "$out" != "  LINK    $b/tests/test_common_vec" ]; then
        echo "make printed $(printf '%s\n' "$out" | wc -l) lines, not one LINK line:"
        printf '%s\n' "$out" | head -5
        return 1
    fi
    rm -f "$b/tests/test_common_vec" "$b/obj/tests/test_common_vec.o"
    out=$(make --no-print-directory CC="$cc" BUILD="$b" V=1 "$b/tests/test_common_vec" 2>&1)
    if ! printf '%s\n' "$out" | grep -q -- "-c tests/test_common_vec.c -o $b/obj/tests/test_common_vec.o"; then
        echo "make V=1 does not show the compile command:"
        printf '%s\n' "$out" | head -5
        return 1
    fi
}

# A suite gets one line; a failed one names its failed tests and its log,
# which holds the whole output.  A stand-in suite that prints as cmocka does.
quiet_suites() {
    local suite=$tmp/suites/test_stand_in out
    mkdir -p "$tmp/suites"
    cat >"$suite" <<'SUITE'
#!/bin/sh
if [ "${1:-}" = --list ]; then printf 'test_good\ntest_bad\n'; exit 0; fi
echo "[==========] Running 2 test(s)."
echo "[ RUN      ] test_good"
echo "[       OK ] test_good"
echo "[ RUN      ] test_bad"
echo "expected 1.5, got 2.5: the stand-in's message"
echo "[  FAILED  ] test_bad"
echo "[==========] 2 test(s) run."
echo "[  PASSED  ] 1 test(s)."
echo "[  FAILED  ] 1 test(s), listed below:"
echo "[  FAILED  ] test_bad"
exit 1
SUITE
    chmod +x "$suite"
    out=$(tools/run-tests.sh "$tmp/suites/results.txt" "$suite" 2>&1)
    local want="  FAIL    $suite: 1 of 2 failed: test_bad (output: $tmp/suites/logs/test_stand_in.log)
$tmp/suites: 1 passed, 1 failed, 0 skipped"
    if [ "$out" != "$want" ]; then
        printf 'run-tests.sh printed:\n%s\nnot:\n%s\n' "$out" "$want"
        return 1
    fi
    grep -q "the stand-in's message" "$tmp/suites/logs/test_stand_in.log" ||
        { echo "the log lacks the suite's output"; return 1; }
    out=$(V=1 tools/run-tests.sh "$tmp/suites/results.txt" "$suite" 2>&1)
    printf '%s\n' "$out" | grep -q "the stand-in's message" || { echo "V=1 does not show the output"; return 1; }
    printf '%s\n' "$out" | grep -qx "==== $suite" || { echo "V=1 does not name the suite"; return 1; }
}

# A renderer before chapter 11 warns of a mesh of more than 4096 triangles
# (common/scene_cost.h); chapter 11's, with its grid, does not.
big_mesh_warning() {
    local k out
    for ((k = 0; k < 4200; k++)); do
        echo "v $k 0 0"
        echo "v $k 1 0"
        echo "v $k 0 1"
        echo "f $((3 * k + 1)) $((3 * k + 2)) $((3 * k + 3))"
    done >"$tmp/big.obj"
    printf '%s\n' '<scene>' '  <surface type="Mesh"><data>big.obj</data></surface>' '</scene>' >"$tmp/big.xml"
    out=$("$build/04_many_shapes/render" -s 2x2 -o "$tmp/big.png" "$tmp/big.xml" 2>&1) || { echo "$out"; return 1; }
    if ! printf '%s\n' "$out" | grep -q "4200 triangles.*chapter 11"; then
        printf 'chapter 04 does not warn of 4200 triangles:\n%s\n' "$out"
        return 1
    fi
    out=$("$build/11_grid/render" -s 2x2 -o "$tmp/big.png" "$tmp/big.xml" 2>&1) || { echo "$out"; return 1; }
    if printf '%s\n' "$out" | grep -q "triangles"; then
        printf 'chapter 11 warns:\n%s\n' "$out"
        return 1
    fi
}

# A bad knob value: one line naming the program and --help, exit status 2,
# no image; --help says where the image goes without -o.
knob_message() {
    local out status
    out=$("$build/07_blinn_phong/render" --phong=x -o "$tmp/knob.png" 2>&1)
    status=$?
    local want="$build/07_blinn_phong/render: --phong: 'x' is not one of: course lecture (see --help)"
    if [ "$status" != 2 ] || [ "$out" != "$want" ] || [ -e "$tmp/knob.png" ]; then
        printf 'exit status %s and:\n%s\nnot 2 and:\n%s\n' "$status" "$out" "$want"
        return 1
    fi
    # a number outside the range its help states (at most 256 bounces, a weight from 0) is refused the same way
    local value
    for value in depth=257 depth=-1 min-weight=-0.5; do
        out=$("$build/11_grid/render" "--$value" -o "$tmp/knob.png" 2>&1)
        status=$?
        local want="^$build/11_grid/render: --${value%%=*}: .* (see --help)$"
        if [ "$status" != 2 ] || ! printf '%s\n' "$out" | grep -q "$want" || [ -e "$tmp/knob.png" ]; then
            printf -- '--%s: exit status %s and:\n%s\n' "$value" "$status" "$out"
            return 1
        fi
    done
    "$build/07_blinn_phong/render" --help | grep -q -- "--output FILE .*(default: 07_blinn_phong.png in the current folder)" ||
        { echo "--help does not say where the image goes without -o"; return 1; }
}

check "each build variant has its own image folder" image_folders
check "building needs no gnuplot, the figures do" no_gnuplot_for_building
check "make prints one line per program, V=1 every command" quiet_build
check "a suite prints one line, its output goes to a log" quiet_suites
check "a renderer before chapter 11 warns of a big mesh" big_mesh_warning
check "a bad knob names the program and --help" knob_message
# The grader lets a student's test start no process (fork, system, popen:
# docs/instructor-guide.md): no graded suite, nor what it links of tests/, may.
no_processes() {
    ! grep -nE '\<(system|popen|fork|vfork|posix_spawnp?|exec[lv]p?e?)[[:space:]]*\(' \
        tests/test_[0-9][0-9]_*.c tests/suite.c tests/answers.c tests/image_compare.c tests/seeded/*.c tests/*.h
}
check "no graded suite starts a process" no_processes
# A student's copy (make handout) describes only what it has, refuses the
# targets it cannot run with one line, and leaves out the instructor's texts.
student_copy() {
    local copy=$tmp/copy words='solutions/|bench/|fuzz/|make (skeletons|handout|autograder|snippets)' out status
    make -s --no-print-directory handout DEST="$copy" >/dev/null || return 1
    if grep -nE "$words" "$copy/README.md"; then
        echo "the copy's README.md names what the copy has not (above)"
        return 1
    fi
    if make -s --no-print-directory -C "$copy" help | grep -E "$words"; then
        echo "the copy's make help names what the copy has not (above)"
        return 1
    fi
    local target
    for target in fuzz skeletons snippets; do
        out=$(make -s --no-print-directory -C "$copy" "$target" 2>&1 >/dev/null | grep -v '^make: \*\*\*')
        status=$?
        if ! printf '%s
' "$out" | grep -q "^make $target: .* student's copy"; then
            echo "make $target in the copy says: '$out'"
            return 1
        fi
    done
    local f
    for f in docs/instructor-guide.md docs/CONTRIBUTING.md; do
        [ -e "$copy/$f" ] && { echo "the copy has $f"; return 1; }
    done
    (cd "$copy" && tools/check-links.sh) || { echo "the copy has links that lead nowhere"; return 1; }
}

# What a graded chapter links, in words (make grade prints it).
grade_words() {
    local got
    got=$(make -s --no-print-directory -f Makefile -f - show <<<'show: ; @echo "$(call grade_links,04_many_shapes)"')
    local want="04_many_shapes: chapters/04_many_shapes/closest_hit.c, with chapters 01 02 03 from the reference (solutions/)"
    [ "$got" = "$want" ] || { printf 'got:  %s
want: %s
' "$got" "$want"; return 1; }
    got=$(make -s --no-print-directory SOURCE=reference -f Makefile -f - show <<<'show: ; @echo "$(call grade_links,04_many_shapes)"')
    want="04_many_shapes: chapters 01 02 03 04 from the reference (solutions/)"
    [ "$got" = "$want" ] || { printf 'got:  %s
want: %s
' "$got" "$want"; return 1; }
}

[ -d solutions ] && check "a student's copy describes only what it has" student_copy
[ -d solutions ] && check "make grade says plainly what it links" grade_words
# The suites' hints for planted mistakes (tests/hints.sh; needs solutions/,
# which a student's copy has not).
[ -d solutions ] && check "the suites' hints name planted mistakes" env CC="$cc" tests/hints.sh "$tmp/hints"

echo "tests/make.sh: $((count - failed)) of $count checks passed"
[ "$failed" -eq 0 ]
