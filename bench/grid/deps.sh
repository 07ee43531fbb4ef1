#!/bin/sh
# deps.sh - the Debian packages `make bench-grid` needs, installed as
# tools/deps.sh installs the build's: libembree-dev (Intel Embree 3, the
# renderer to compare with) and glmark2-data (the Stanford bunny as OBJ).
missing=""
dpkg -s libembree-dev >/dev/null 2>&1 || missing="$missing libembree-dev"
dpkg -s glmark2-data >/dev/null 2>&1 || missing="$missing glmark2-data"
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    apt=apt-get
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    apt="sudo apt-get"
else
    echo "bench-grid: missing Debian packages:$missing (install them with: sudo apt-get install$missing)" >&2
    exit 1
fi
echo "bench-grid: installing Debian packages:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
$apt update -qq >/dev/null && $apt install -y -qq $missing >/dev/null || {
    echo "bench-grid: could not install the Debian packages:$missing" >&2
    exit 1
}
