#!/bin/sh
# regen.sh - regenerates golden files from the current ./utak. A deliberate act:
# afterwards read `git diff tests/` line by line, and say in the commit why the
# output changed. Malformed-input messages (tests/bad/*.err) are regenerated too,
# and the pictures (NAME.svg) and replays' data (NAME.replay) of golden runs that
# have them (tests/run.sh).
utak=$1
for args in tests/golden/*.args; do
	[ -f "$args" ] || continue
	name=${args%.args}
	eval "set -- $(cat "$args")"
	[ -f "$name.svg" ] && set -- "$@" --svg "$name.svg"
	[ -f "$name.replay" ] && set -- "$@" --html "$name.html"
	"$utak" "$@" >"$name.out" 2>/dev/null; st=$?
	if [ -f "$name.replay" ]; then sh tests/replay-data.sh "$name.html" >"$name.replay"; rm -f "$name.html"; fi
	if [ "$st" != 0 ]; then echo "$st" >"$name.code"; else rm -f "$name.code"; fi
done
for input in tests/bad/*.w tests/bad/*.args; do
	[ -f "$input" ] || continue
	name=${input%.*}
	case $input in
	*.w) "$utak" "$input" >/dev/null 2>"$name.err" ;;
	*) eval "set -- $(cat "$input")"; "$utak" "$@" >/dev/null 2>"$name.err" ;;
	esac
done
git status --short tests/
