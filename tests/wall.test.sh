#!/bin/sh
# wall.test.sh - the layers of the tree, and the wall between body and mind (paper
# 3.1), checked from the sources and from the objects.
#
# THE FOLDER RULE. Each folder of src/ is a layer that may use only the layers
# listed for it here (README.md, "Architecture"):
#
#   base   libc only: geometry, the eye's anatomy, the task statement, plumbing
#   plan   base: the spatial planner on any occupancy grid (libutak-plan.a)
#   body   base: the simulator, paper 2.1-2.2
#   mind   base, plan: the controller, paper 3
#   src/   main.c, svg.c and replay.c own both sides and may use everything
#
# include/utak/impression.h, the wall itself (an impression goes from body to mind,
# a motor command from mind to body), belongs to every layer.
#
# Two checks, either of which fails the test:
#   1. every utak header a source reaches through its #include lines, transitively,
#      lies in a layer the source's layer may use;
#   2. every symbol its object file (`nm -u`) needs that some other layer's object
#      defines is defined in a layer it may use: a declaration written by hand
#      instead of an #include does not get through.
#
# EXCEPTIONS, each with its reason and the issue that removes it: none. (The judge
# used plan and mind/{rooms,shape} until issue 13 gave it rules of its own:
# body/judgeshape.c and body/judgerooms.c.)
EXCEPTIONS=""

cd "$(dirname "$0")/.." || exit 2
status=0
tmp=${TMPDIR:-/tmp}/utak-wall.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM

# allowed LAYER: the layers LAYER may use, itself included.
allowed() {
	case $1 in
	base) echo "base" ;;
	plan) echo "base plan" ;;
	body) echo "base body" ;;
	mind) echo "base plan mind" ;;
	*) echo "base plan body mind top" ;;
	esac
}

# allowed_for FILE: allowed LAYER plus the file's exceptions.
allowed_for() {
	layer=$(layer_of "$1")
	extra=""
	for e in $EXCEPTIONS; do
		[ "${e%%:*}" = "$1" ] && extra="$extra $(echo "${e#*:}" | tr , ' ')"
	done
	echo "$(allowed "$layer")$extra"
}

# layer_of PATH: the layer of a source or header path; "top" for src/main.c,
# src/svg.c, src/replay.c and the top-level headers other than impression.h.
layer_of() {
	case $1 in
	*/impression.h) echo "wall" ;;
	src/base/* | include/utak/base/*) echo base ;;
	src/plan/* | include/utak/plan/*) echo plan ;;
	src/body/* | include/utak/body/*) echo body ;;
	src/mind/* | include/utak/mind/*) echo mind ;;
	*) echo top ;;
	esac
}

# includes FILE: the utak headers FILE names, as paths under include/.
includes() {
	sed -n 's/^[ 	]*#[ 	]*include[ 	]*["<]\(utak\/[a-z_0-9/]*\.h\)[">].*/include\/\1/p' "$1"
}

# closure FILE: every utak header reached from FILE, transitively.
closure() {
	seen=""; todo=$(includes "$1")
	while :; do
		next=""
		for h in $todo; do
			case " $seen " in *" $h "*) continue ;; esac
			seen="$seen $h"
			[ -f "$h" ] && next="$next $(includes "$h")"
		done
		[ -z "$(echo $next)" ] && break
		todo=$next
	done
	echo $seen
}

sources=$(ls src/*.c src/*/*.c 2>/dev/null)
[ -n "$sources" ] || { echo "wall: no sources found"; exit 1; }
for layer in base plan body mind; do
	ls src/$layer/*.c >/dev/null 2>&1 || { echo "wall: src/$layer/ is empty"; status=1; }
done

# Check 1: the #include closure of every source.
for src in $sources; do
	ok=$(allowed_for "$src")
	for h in $(closure "$src"); do
		[ -f "$h" ] || { echo "wall: $src includes $h, which does not exist"; status=1; continue; }
		hl=$(layer_of "$h")
		[ "$hl" = wall ] && continue
		case " $ok " in
		*" $hl "*) ;;
		*) echo "wall: $src ($(layer_of "$src")) reaches $h ($hl)"; status=1 ;;
		esac
	done
done

# Check 2: the symbols. Compile each source on its own, then map every defined
# symbol to its layer. (build/inc holds the replay's viewer, which the build
# generates for replay.c from src/replay.html.)
for src in $sources; do
	obj="$tmp/$(echo "$src" | tr / _).o"
	if ! ${CC:-cc} -std=c11 -D_POSIX_C_SOURCE=200809L -Iinclude -Ibuild/inc -c "$src" -o "$obj" 2>"$tmp/err"; then
		echo "wall: $src does not compile on its own"; cat "$tmp/err"; status=1; continue
	fi
	nm -g --defined-only "$obj" | awk -v l="$(layer_of "$src")" 'NF == 3 {print $3, l}' >>"$tmp/defs"
done
for src in $sources; do
	obj="$tmp/$(echo "$src" | tr / _).o"
	[ -f "$obj" ] || continue
	ok=$(allowed_for "$src")
	nm -u "$obj" | awk '{print $NF}' | sort -u >"$tmp/undef"
	bad=$(awk -v ok=" $ok " 'NR == FNR { need[$1] = 1; next }
		($1 in need) && index(ok, " " $2 " ") == 0 { print $1 "(" $2 ")" }' "$tmp/undef" "$tmp/defs")
	[ -z "$bad" ] || { echo "wall: $src ($(layer_of "$src")) calls" $bad; status=1; }
done
exit $status
