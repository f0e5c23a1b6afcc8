#!/bin/sh
# install.test.sh - the planner library as a user installs it: make install into a
# temporary DESTDIR with PREFIX=/usr, examples/plan.c built against that copy alone
# with `pkg-config --cflags --libs utak-plan` (no -Iinclude, no build/), run and
# compared with the in-tree build's output; then make uninstall must leave no file
# and none of the folders utak made.
cd "$(dirname "$0")/.." || exit 2
tmp=${TMPDIR:-/tmp}/utak-install.$$
dest=$tmp/root
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM
make=${MAKE:-make}
command -v pkg-config >/dev/null || { echo "install: pkg-config is missing (tests/fuzz/need.sh pkg-config installs it)"; exit 1; }

$make -s install DESTDIR="$dest" PREFIX=/usr >"$tmp/log" 2>&1 || { echo "install: make install failed"; cat "$tmp/log"; exit 1; }
for f in usr/bin/utak usr/lib/libutak-plan.a usr/lib/pkgconfig/utak-plan.pc usr/include/utak/impression.h \
	usr/include/utak/plan/skeleton.h usr/include/utak/base/geom.h usr/share/man/man1/utak.1 \
	usr/share/man/man3/utak-plan.3 usr/share/man/man5/utak.5; do
	[ -f "$dest/$f" ] || { echo "install: $f not installed"; exit 1; }
done
# Only the planner's layers are installed: no simulator or controller header.
if [ -d "$dest/usr/include/utak/body" ] || [ -d "$dest/usr/include/utak/mind" ]; then
	echo "install: body/ or mind/ headers installed with the planner library"; exit 1
fi
[ "$(stat -c %a "$dest/usr/bin/utak")" = 755 ] || { echo "install: utak is not mode 755"; exit 1; }
[ "$(stat -c %a "$dest/usr/lib/libutak-plan.a")" = 644 ] || { echo "install: the library is not mode 644"; exit 1; }

export PKG_CONFIG_PATH="$dest/usr/lib/pkgconfig" PKG_CONFIG_SYSROOT_DIR="$dest"
flags=$(pkg-config --cflags --libs utak-plan) || { echo "install: pkg-config does not know utak-plan"; exit 1; }
case $flags in *"$dest/usr/include"*"$dest/usr/lib"*) ;; *) echo "install: pkg-config gives '$flags'"; exit 1 ;; esac
# shellcheck disable=SC2086
${CC:-cc} -std=c11 -o "$tmp/plan" examples/plan.c $flags 2>"$tmp/cc" || { echo "install: the example does not build against the installed library"; cat "$tmp/cc"; exit 1; }
args="tests/data/movingai/maps/dao/arena.map 3 3 45 40"
# shellcheck disable=SC2086
"$tmp/plan" $args >"$tmp/installed.out" || { echo "install: the installed example failed"; exit 1; }
# shellcheck disable=SC2086
build/chk/examples/plan $args >"$tmp/tree.out" || { echo "install: the in-tree example failed"; exit 1; }
cmp -s "$tmp/installed.out" "$tmp/tree.out" || { echo "install: installed and in-tree examples differ"; diff "$tmp/tree.out" "$tmp/installed.out"; exit 1; }

$make -s uninstall DESTDIR="$dest" PREFIX=/usr >"$tmp/log" 2>&1 || { echo "install: make uninstall failed"; cat "$tmp/log"; exit 1; }
left=$(cd "$dest" && { find . -type f; find . -path "*utak*"; })
[ -z "$left" ] || { echo "install: make uninstall left behind:"; echo "$left"; exit 1; }
exit 0
