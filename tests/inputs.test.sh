#!/bin/sh
# inputs.test.sh - the other ways in and out of a run (utak(1)), each against the
# plain way as its oracle:
#   - "-" reads the world from standard input: the same output as the file, for a
#     task and for --act; a bad world there is named "standard input" in the
#     message, which is otherwise the file's;
#   - --act-file FILE, --act @FILE and --act-file - read a script with '#' comments
#     and give the same run as the same commands inline;
#   - --svg draws an --act run: a picture whose trail holds the start and one point
#     per command, and whose title counts the commands;
#   - -n with --act says how many commands the script holds.
tmp=${TMPDIR:-/tmp}/utak-inputs.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# same WHAT: the two last runs ($tmp/a, $tmp/b: stdout, stderr, status) agree.
same() {
	cmp -s "$tmp/a" "$tmp/b" || { fail "$1: outputs differ"; diff "$tmp/a" "$tmp/b" | head -n 5; }
}

# The world from standard input.
"$UTAK" -q worlds/tworooms.w "go next-room" >"$tmp/a" 2>&1; echo "status $?" >>"$tmp/a"
"$UTAK" -q - "go next-room" <worlds/tworooms.w >"$tmp/b" 2>&1; echo "status $?" >>"$tmp/b"
same "- for a task"
script="move 3 8; grasp; push 5 0; turn 30; release; move -2 -1"
"$UTAK" worlds/room.w --act "$script" >"$tmp/a" 2>&1
"$UTAK" - --act "$script" <worlds/room.w >"$tmp/b" 2>&1
same "- for --act"
for bad in tests/bad/unknown-keyword.w tests/bad/objects-overlap.w tests/bad/empty.w; do
	"$UTAK" - <"$bad" >/dev/null 2>"$tmp/b"; st=$?
	[ "$st" = 2 ] || fail "- with $bad: exit status $st, want 2"
	sed "s|^utak: $bad|utak: standard input|" "${bad%.w}.err" >"$tmp/a"
	same "- with $bad"
done

# A script from a file, with comments, against the same commands inline.
cat >"$tmp/tour.act" <<'EOF'
# A tour of room.w: to the brick, push it east, turn it, let go.
move 3 8        # up beside the brick
grasp
push 5 0; turn 30   # two on a line
# a comment line between commands

release
move -2 -1#no blank before the comment
EOF
for how in "--act-file $tmp/tour.act" "--act @$tmp/tour.act" "--act-file -"; do
	# shellcheck disable=SC2086
	"$UTAK" worlds/room.w $how <"$tmp/tour.act" >"$tmp/b" 2>&1
	"$UTAK" worlds/room.w --act "$script" >"$tmp/a" 2>&1
	same "$how"
done
"$UTAK" -n worlds/room.w --act-file "$tmp/tour.act" >"$tmp/b" 2>&1
echo "act: 6 motor commands" >"$tmp/a"
same "-n --act-file"

# --svg with --act.
"$UTAK" worlds/room.w --act "$script" --svg "$tmp/act.svg" >/dev/null 2>"$tmp/err" || fail "--svg --act: status $?"
[ ! -s "$tmp/err" ] || fail "--svg --act: $(cat "$tmp/err")"
python3 - "$tmp/act.svg" <<'PY' || fail "--svg --act: the picture"
import re, sys
import xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[1]).getroot()
trail = next(e for e in root.iter() if e.get("id") == "trail")
points = re.findall(r"-?\d+(?:\.\d+)?,-?\d+(?:\.\d+)?", trail.get("points"))
# The start and the three commands that moved him, none of them straight on from the
# one before: grasp, turn and release leave him where he is, so they make no corner.
assert len(points) == 4, points
title = root.find(ns + "title").text
assert "6 motor commands" in title, title
PY

[ $fails = 0 ]
