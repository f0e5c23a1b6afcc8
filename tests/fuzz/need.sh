#!/bin/sh
# need.sh - installs Debian packages that the optional checks need, only when they
# are missing (issue 6): clang and its libFuzzer runtime for `make fuzz`,
# libbox2d-dev and g++ for `make xcheck`. The main build needs none of them.
#
#   sh tests/fuzz/need.sh PACKAGE...
#
# A package counts as present when dpkg says it is installed. Missing packages
# are installed with apt-get (after apt-get update) when we are root; otherwise
# the script says what to install and fails. NEED_DRY_RUN=1 only says what it
# would do, to test this logic on a machine that has everything.
missing=
for pkg in "$@"; do
	dpkg -s "$pkg" 2>/dev/null | grep -q '^Status: install ok installed' || missing="$missing $pkg"
done
[ -z "$missing" ] && exit 0
if [ -n "$NEED_DRY_RUN" ]; then
	echo "need.sh: would install:$missing"
	exit 0
fi
if [ "$(id -u)" != 0 ]; then
	echo "need.sh: missing:$missing (as root: apt-get install$missing)" >&2
	exit 1
fi
echo "need.sh: installing:$missing"
export DEBIAN_FRONTEND=noninteractive
# Another apt-get (unattended upgrades on a fresh machine, a second job) may hold
# dpkg's lock: wait for it up to ten minutes rather than fail at once.
lock="-o DPkg::Lock::Timeout=600"
apt-get $lock update -qq && apt-get $lock install -y -qq --no-install-recommends $missing >/dev/null || {
	echo "need.sh: apt-get could not install:$missing" >&2
	exit 1
}
