#!/bin/bash
# autograder.sh ZIP CHAPTER TIMEOUT DOUBLE_LIBS FLOAT_LIBS [BUDGET] - a Gradescope autograder.
#
# The zip holds, at its root (Gradescope unpacks it into /autograder/source),
# a student's copy of the project (tools/handout.sh: no solution source, the
# compiled reference libraries from DOUBLE_LIBS and FLOAT_LIBS), Gradescope's
# setup.sh and run_autograder, and grade.conf (CHAPTER, 01 or 01_camera_rays,
# empty for every chapter, TIMEOUT, seconds per test, and BUDGET, seconds for
# the whole grading, 1200 unless given).
#
# setup.sh (once, as root, on Gradescope's Ubuntu 22.04 image) installs the
# Debian packages, creates the unprivileged user the tests run as, closes
# the source folder to everyone but root, and checks that the reference gets
# full marks, running as that user.  run_autograder (for each submission)
# takes the graded chapter's exercise files from the submission
# (tools/take-submission.sh) and runs `make grade GRADE_USER=...`: the
# student's code runs as that user, which can read nothing of the grader's,
# and the results go to /autograder/results/results.json.  Both take
# AUTOGRADER_ROOT=dir instead of /autograder, for a trial run
# (docs/instructor-guide.md).
set -u
zip=${1:?usage: autograder.sh ZIP CHAPTER TIMEOUT DOUBLE_LIBS FLOAT_LIBS}
chapter=$2
timeout=${3:-10}
double_libs=${4:?} float_libs=${5:?}
budget=${6:-1200}

if ! command -v zip >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ]; then
        apt="apt-get"
    elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
        apt="sudo apt-get"
    else
        echo "missing Debian package: zip (install it with: sudo apt-get install zip)" >&2
        exit 1
    fi
    echo "installing the missing Debian package zip" >&2
    DEBIAN_FRONTEND=noninteractive $apt install -y -qq zip >/dev/null 2>&1 ||
        { $apt update -qq >/dev/null && DEBIAN_FRONTEND=noninteractive $apt install -y -qq zip >/dev/null; } ||
        { echo "could not install the Debian package zip" >&2; exit 1; }
fi

stage=$(mktemp -d) || exit 1
trap 'rm -rf "$stage"' EXIT
tools/handout.sh "$stage/zip" "$double_libs" "$float_libs" >/dev/null || exit 1
printf 'CHAPTER=%s\nTIMEOUT=%s\nBUDGET=%s\n' "$chapter" "$timeout" "$budget" >"$stage/zip/grade.conf"

cat >"$stage/zip/setup.sh" <<'SETUP'
#!/bin/bash
# Gradescope runs this once, as root, when it builds the autograder image
# (Ubuntu 22.04).  AUTOGRADER_ROOT=dir stands for /autograder in a trial run;
# AUTOGRADER_NO_APT=1 skips apt-get there.
set -euo pipefail
root=${AUTOGRADER_ROOT:-/autograder}
user=rtgrade # the unprivileged user the student's code runs as
if [ -z "${AUTOGRADER_NO_APT:-}" ]; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends make gcc libc6-dev binutils coreutils \
        libexpat1-dev libstb-dev libcmocka-dev >/dev/null
fi
id -u "$user" >/dev/null 2>&1 ||
    useradd --system --no-create-home --home-dir /nonexistent --shell /usr/sbin/nologin "$user"
cd "$root/source"
. ./grade.conf
# Only root reads the project, the builds and the skeletons kept for run_autograder.
chown -R root:root "$root/source"
chmod -R go-rwx "$root/source"
rm -rf pristine && cp -R chapters pristine
# The reference must get full marks, run as the user, which also builds everything once.
make --no-print-directory grade SOURCE=reference CHAPTER="$CHAPTER" TIMEOUT="$TIMEOUT" GRADE_USER="$user" \
    GRADE_JSON=build-grade/reference.json GRADE_JUNIT=build-grade/reference.xml
SETUP

cat >"$stage/zip/run_autograder" <<'RUN'
#!/bin/bash
# Gradescope runs this, as root, for every submission.  The graded chapter's
# exercise files are taken from the submission (tools/take-submission.sh says
# which, and which are missing); the tests run as the unprivileged user, and
# only root can write the results.  AUTOGRADER_ROOT=dir stands for /autograder.
root=${AUTOGRADER_ROOT:-/autograder}
user=rtgrade
cd "$root/source" || exit 1
. ./grade.conf
mkdir -p "$root/results"
chown root:root "$root/results"
chmod 755 "$root/results"
rm -f "$root/results/results.json"
notes=build-grade/submission.txt
mkdir -p build-grade
tools/take-submission.sh "$root/submission" pristine "$CHAPTER" >"$notes"
make --no-print-directory grade CHAPTER="$CHAPTER" TIMEOUT="$TIMEOUT" GRADE_BUDGET="$BUDGET" GRADE_USER="$user" \
    GRADE_NOTES="$notes" \
    GRADE_JSON="$root/results/results.json" GRADE_JUNIT=build-grade/junit.xml
if [ ! -s "$root/results/results.json" ]; then
    printf '{"score": 0, "output": "The grader could not run; please tell the course staff.", "tests": []}\n' \
        >"$root/results/results.json"
fi
RUN
chmod 755 "$stage/zip/setup.sh" "$stage/zip/run_autograder"

# The zip must hold no solution source either.
tools/handout.sh --check "$stage/zip" >/dev/null || exit 1
mkdir -p "$(dirname "$zip")"
case "$zip" in /*) out=$zip ;; *) out=$(pwd)/$zip ;; esac
rm -f "$out"
(cd "$stage/zip" && zip -qr "$out" .) || exit 1
echo "wrote $zip (grades ${chapter:-every chapter}; no solution source; upload it as a Gradescope autograder)"
