#!/bin/sh
# deps.sh CC [GROUP...] - make sure the Debian packages the build needs are installed.
#
# With the group `fuzz` (make fuzz), the packages of the fuzz targets instead:
# clang with libFuzzer and the sanitizers, and expat; the default build's own
# packages are left as they are.  Other groups add the needs of one target:
# figures (make figures and make check: gnuplot-nox for the plotted figures),
# bench (make bench: gnuplot-nox for the plots, povray for the comparison
# with POV-Ray) and bench-grid (make bench-grid: libembree-dev, Intel Embree
# 3, to compare the grid with, and glmark2-data, the Stanford bunny as OBJ),
# book (make book: pandoc and KaTeX, libjs-katex) and book-check (make
# check-book: Debian's chromium, driven by nodejs).
#
# Each need is probed by compiling a one-line program with CC.  What is
# missing is installed with apt-get (as root) or sudo apt-get (when sudo works
# without a password); otherwise (or with DEPS_NO_INSTALL=1, as tests/make.sh
# runs it) one line names the packages and the build stops.
cc=${1:-cc}
[ $# -gt 0 ] && shift
missing=""
mode=build
needs_gnuplot=0
for group in "$@"; do
    case "$group" in
        fuzz) mode=fuzz ;;
        figures) needs_gnuplot=1 ;;
        bench)
            needs_gnuplot=1
            command -v povray >/dev/null 2>&1 || missing="$missing povray"
            ;;
        bench-grid)
            dpkg -s libembree-dev >/dev/null 2>&1 || missing="$missing libembree-dev"
            dpkg -s glmark2-data >/dev/null 2>&1 || missing="$missing glmark2-data"
            ;;
        book)
            command -v pandoc >/dev/null 2>&1 || missing="$missing pandoc"
            [ -f /usr/share/javascript/katex/katex.min.js ] || missing="$missing libjs-katex"
            ;;
        book-check)
            command -v chromium >/dev/null 2>&1 || missing="$missing chromium"
            command -v node >/dev/null 2>&1 || missing="$missing nodejs"
            ;;
        *) echo "deps.sh: unknown group '$group' (known: fuzz, figures, bench, bench-grid, book, book-check)" >&2; exit 2 ;;
    esac
done

probe() { # package, program, extra flags
    printf '%s\n' "$2" | $cc $3 -x c -fsyntax-only - >/dev/null 2>&1 || missing="$missing $1"
}

if [ "$mode" = fuzz ]; then
    if ! command -v "$cc" >/dev/null 2>&1; then
        missing="$missing clang libclang-rt-dev libexpat1-dev libstb-dev"
    else
        probe libexpat1-dev '#include <expat.h>'
        probe libstb-dev '#include <stb/stb_image.h>'
        # libFuzzer and the sanitizer runtimes: a link, not only a compile.
        exe=$(mktemp)
        printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
            'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }' |
            $cc -fsanitize=fuzzer,address,undefined -x c - -o "$exe" >/dev/null 2>&1 ||
            missing="$missing libclang-rt-dev"
        rm -f "$exe"
    fi
elif ! command -v "$cc" >/dev/null 2>&1; then
    case "$cc" in
        clang*) missing="$missing clang libomp-dev" ;;
        gcc-[0-9]*) missing="$missing $cc" ;; # Debian's gcc-11, gcc-12, ...
        *) missing="$missing gcc" ;;
    esac
else
    probe libexpat1-dev '#include <expat.h>'
    probe libstb-dev '#include <stb/stb_image_write.h>'
    probe libcmocka-dev '#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>'
    case "$($cc --version 2>/dev/null)" in
        *clang*) probe libomp-dev '#include <omp.h>' -fopenmp ;;
        *) probe libgomp1 '#include <omp.h>' -fopenmp ;;
    esac
fi
command -v timeout >/dev/null 2>&1 || missing="$missing coreutils"
if [ "$needs_gnuplot" = 1 ]; then
    command -v gnuplot >/dev/null 2>&1 || missing="$missing gnuplot-nox"
fi

[ -z "$missing" ] && exit 0

if [ -n "${DEPS_NO_INSTALL:-}" ]; then
    apt=
elif [ "$(id -u)" = 0 ]; then
    apt=apt-get
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    apt="sudo apt-get"
else
    apt=
fi
if [ -z "$apt" ]; then
    echo "missing Debian packages:$missing (install them with: sudo apt-get install$missing)" >&2
    exit 1
fi
echo "installing missing Debian packages:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
$apt update -qq >/dev/null && $apt install -y -qq $missing >/dev/null || {
    echo "could not install the Debian packages:$missing" >&2
    exit 1
}
