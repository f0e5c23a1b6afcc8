#!/bin/sh
# wall.test.sh - the wall between body and mind (impression.h), checked.
#
# The controller knows the world only through Impressions and its own
# MotorCommands. So no controller source may include a simulator header, directly
# or through another header, and no controller object may call a simulator
# function. Run by tests/run.sh from the top directory; exits 1 on a breach.
#
# THE ONE LIST: the simulator's modules. Every other src/*.c except main.c (which
# owns both sides) is on the controller's side of the wall, or shared.
# judge and svg read the real world too: the ground-truth verdict and the picture of
# a run (which shows the world beside what Utak believed).
SIMULATOR="world table motion retina judge svg"

cd "$(dirname "$0")/.." || exit 2
status=0
tmp=${TMPDIR:-/tmp}/utak-wall.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM

is_simulator() {
	for s in $SIMULATOR; do [ "$1" = "$s" ] && return 0; done
	return 1
}

# includes FILE: the utak headers FILE names, one per line, without directory.
includes() {
	sed -n 's/^[ 	]*#[ 	]*include[ 	]*["<]utak\/\([a-z_0-9]*\)\.h[">].*/\1/p' "$1"
}

# closure FILE: every utak header reached from FILE, transitively.
closure() {
	seen=""; todo=$(includes "$1")
	while :; do
		next=""
		for h in $todo; do
			case " $seen " in *" $h "*) continue ;; esac
			seen="$seen $h"
			[ -f "include/utak/$h.h" ] && next="$next $(includes "include/utak/$h.h")"
		done
		[ -z "$(echo $next)" ] && break
		todo=$next
	done
	echo $seen
}

forbidden_headers=""
for s in $SIMULATOR; do forbidden_headers="$forbidden_headers $s"; done
symbols=$(echo $SIMULATOR | sed 's/\([a-z]*\)/\1_/g; s/ /|/g')

checked=0
for src in src/*.c; do
	mod=$(basename "$src" .c)
	[ "$mod" = main ] && continue
	is_simulator "$mod" && continue
	checked=$((checked + 1))
	for h in $(closure "$src"); do
		case " $forbidden_headers " in
		*" $h "*) echo "wall: $src reaches the simulator header $h.h"; status=1 ;;
		esac
	done
	if ! ${CC:-cc} -std=c11 -D_POSIX_C_SOURCE=200809L -Iinclude -c "$src" -o "$tmp/$mod.o" 2>"$tmp/err"; then
		echo "wall: $src does not compile on its own"; cat "$tmp/err"; status=1; continue
	fi
	bad=$(nm -u "$tmp/$mod.o" | awk '{print $NF}' | grep -E "^($symbols)" || true)
	if [ -n "$bad" ]; then
		echo "wall: $src calls simulator functions:" $bad; status=1
	fi
done
[ "$checked" -gt 0 ] || { echo "wall: no controller sources found"; status=1; }
exit $status
