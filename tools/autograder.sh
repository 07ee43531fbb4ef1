#!/bin/sh
# autograder.sh ZIP [CHAPTER] [TIMEOUT] - a Gradescope autograder for the project.
#
# The zip holds, at its root (Gradescope unpacks it into /autograder/source), what Gradescope asks for (setup.sh and
# run_autograder) and the project itself: Makefile, common/, chapters/,
# solutions/, tests/, tools/.  setup.sh installs the Debian packages and
# checks that the solutions get full marks; run_autograder copies the
# student's exercise files from /autograder/submission over the skeletons
# and runs `make grade`, which writes /autograder/results/results.json.
# CHAPTER (01 or 01_camera_rays; empty: every chapter) is what is graded.
zip=$1
chapter=$2
timeout=${3:-10}
[ -n "$zip" ] || { echo "usage: $0 ZIP [CHAPTER] [TIMEOUT]" >&2; exit 2; }

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
cp -R Makefile common chapters solutions tests tools "$stage/" || exit 1
printf 'CHAPTER=%s\nTIMEOUT=%s\n' "$chapter" "$timeout" >"$stage/grade.conf"

cat >"$stage/setup.sh" <<'SETUP'
#!/bin/bash
# Gradescope runs this once, as root, when it builds the autograder image.
set -e
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq make gcc libexpat1-dev libstb-dev libcmocka-dev coreutils >/dev/null
mkdir -p /autograder/source
cd /autograder/source
. ./grade.conf
# The solutions must get full marks, which also builds everything once.
make --no-print-directory grade SOURCE=solutions CHAPTER="$CHAPTER" TIMEOUT="$TIMEOUT" \
    GRADE_JSON=/tmp/solutions.json GRADE_JUNIT=/tmp/solutions.xml
SETUP

cat >"$stage/run_autograder" <<'RUN'
#!/bin/bash
# Gradescope runs this for every submission.  The student's exercise files
# replace the skeletons: a file is taken from the submission by its path
# (.../NN_name/FILE.c) or, when no other chapter has a file of that name, by
# its name alone.  Nothing else of the submission is used.
root=${AUTOGRADER_ROOT:-/autograder} # another root for a trial run
cd "$root/source" || exit 1
. ./grade.conf
mkdir -p "$root/results"
rm -f "$root/results/results.json"
for solution in solutions/[0-9][0-9]_*/*.c; do
    rel=${solution#solutions/}
    ch=${rel%%/*}
    file=${rel#*/}
    if [ -n "$CHAPTER" ]; then
        case "$ch" in "$CHAPTER"*) ;; *) continue ;; esac
    fi
    tools/skeletons.sh write "$solution" >/dev/null # the skeleton, should a file be missing
    found=$(find "$root/submission" -type f -path "*/$ch/$file" | head -n 1)
    if [ -z "$found" ] && [ "$(ls solutions/*/"$file" | wc -l)" = 1 ]; then
        found=$(find "$root/submission" -type f -name "$file" | head -n 1)
    fi
    if [ -n "$found" ]; then
        cp "$found" "chapters/$ch/$file"
        echo "chapters/$ch/$file: from ${found#"$root"/submission/}"
    else
        echo "chapters/$ch/$file: not in the submission; the skeleton is graded"
    fi
done
make --no-print-directory grade CHAPTER="$CHAPTER" TIMEOUT="$TIMEOUT" \
    GRADE_JSON="$root/results/results.json" GRADE_JUNIT="$root/results/junit.xml"
[ -s "$root/results/results.json" ] || echo '{"score": 0, "output": "the grader did not run; see the autograder output", "tests": []}' >"$root/results/results.json"
RUN
chmod +x "$stage/setup.sh" "$stage/run_autograder"

mkdir -p "$(dirname "$zip")"
case "$zip" in /*) out=$zip ;; *) out=$(pwd)/$zip ;; esac
rm -f "$out"
(cd "$stage" && zip -qr "$out" .) || exit 1
echo "wrote $zip (grades ${chapter:-every chapter}; upload it as a Gradescope autograder)"
