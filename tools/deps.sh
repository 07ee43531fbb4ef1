#!/bin/sh
# deps.sh CC [GROUP...] - make sure the Debian packages the build needs are installed.
#
# Each need is probed by compiling a one-line program with CC.  What is
# missing is installed with apt-get (as root) or sudo apt-get (when sudo works
# without a password); otherwise one line names the packages and the build stops.
# Optional groups add the needs of one target: bench (make bench: gnuplot-nox
# for the plots, povray for the comparison with POV-Ray).
cc=${1:-cc}
[ $# -gt 0 ] && shift
missing=""
for group in "$@"; do
    case "$group" in
        bench)
            command -v gnuplot >/dev/null 2>&1 || missing="$missing gnuplot-nox"
            command -v povray >/dev/null 2>&1 || missing="$missing povray"
            ;;
        *) echo "deps.sh: unknown group '$group' (known: bench)" >&2; exit 2 ;;
    esac
done

probe() { # package, program, extra flags
    printf '%s\n' "$2" | $cc $3 -x c -fsyntax-only - >/dev/null 2>&1 || missing="$missing $1"
}

if ! command -v "$cc" >/dev/null 2>&1; then
    case "$cc" in
        clang*) missing="$missing clang libomp-dev" ;;
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

[ -z "$missing" ] && exit 0

if [ "$(id -u)" = 0 ]; then
    apt=apt-get
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    apt="sudo apt-get"
else
    echo "missing Debian packages:$missing (install them with: sudo apt-get install$missing)" >&2
    exit 1
fi
echo "installing missing Debian packages:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
$apt update -qq >/dev/null && $apt install -y -qq $missing >/dev/null || {
    echo "could not install the Debian packages:$missing" >&2
    exit 1
}
