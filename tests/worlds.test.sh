#!/bin/sh
# worlds.test.sh - no undefined behaviour on any world we have (issue 14): the
# sanitizer build that `make check` passes as UTAK (ASan + UBSan, no recovery, so
# any finding aborts) runs over every world file in tests/ and worlds/, the bad
# ones included, with a script of motor commands that moves, grasps, pushes, turns
# and lets go, and makes moves of a million squares, and with a task. A world that
# loads must run to exit status 0 (or 1 for a task not achieved); one that does
# not must give status 2 and one line "utak: ...". Either way nothing else on
# standard error: a sanitizer's report is a failure even if the status looks right.
script="move 3 2; grasp; push 2 1; turn 45; release; turn -90; move 1000000 0; move -1000000 -1000000; grasp; push 0 1000000; turn 1000000"
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
tmp=${TMPDIR:-/tmp}/utak-worlds.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM

# check WORLD WHAT WANT: the last run's status ($st) is one of WANT, stderr is
# empty, or for status 2 one line from utak.
check() {
	case " $3 " in *" $st "*) ;; *) fail "$1 ($2): exit status $st, want one of $3"; head -n 5 "$tmp/err" ;; esac
	if [ "$st" = 2 ]; then
		[ "$(wc -l <"$tmp/err")" = 1 ] && grep -q '^utak: ' "$tmp/err" ||
			{ fail "$1 ($2): not one line from utak"; head -n 5 "$tmp/err"; }
	elif [ -s "$tmp/err" ]; then
		fail "$1 ($2): wrote to standard error"; head -n 5 "$tmp/err"
	fi
}

n=0
for w in $(find tests worlds -name '*.w' | LC_ALL=C sort); do
	n=$((n + 1))
	"$UTAK" "$w" --act "$script" --dump model >/dev/null 2>"$tmp/err"; st=$?
	check "$w" "--act" "0 2"
	[ "$st" = 0 ] || continue
	"$UTAK" -q --max-cycles 40 "$w" "go ne-corner" >/dev/null 2>"$tmp/err"; st=$?
	check "$w" "go ne-corner" "0 1"
	"$UTAK" -q --max-cycles 40 "$w" "go square" >/dev/null 2>"$tmp/err"; st=$?
	check "$w" "go square" "0 1"
done
[ $n -ge 100 ] || fail "only $n worlds found"
[ $fails = 0 ]
