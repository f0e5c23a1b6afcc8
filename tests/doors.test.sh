#!/bin/sh
# doors.test.sh - the simplest two-room worlds (doorsure.h; paper 2.3 task (i)): a
# 40 x 30 TABLE cut by one wall across at row 18 with a door. Each case below was
# a false success at 49e82b6 (Utak sure of the corner, the judge: in the next room,
# or short of the corner of the one room the judge counts); the simulator's judge
# is the oracle. None may end "(Utak believes it achieved)" with the judge saying
# failed, and the cases achieved by looking first must stay achieved.
# Case: THICKNESS DOOR-WIDTH DOOR-X HEADING CORNER WANT (a: achieved, sure or
# not; h: not a false success).
fails=0
tmp=${TMPDIR:-/tmp}/utak-doors.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM
while read -r th dw x0 h corner want; do
	cat >"$tmp/t.w" <<EOW
table 40 30
wall 1 18 $x0 18 $x0 $((18 + th)) 1 $((18 + th))
wall $((x0 + dw)) 18 39 18 39 $((18 + th)) $((x0 + dw)) $((18 + th))
utak 15.5 7.5 $h
EOW
	r=$("$UTAK" -q "$tmp/t.w" "go $corner-corner" 2>&1 | tail -n 1)
	case "$r" in
	*"believes it achieved"*) echo "FAIL: th=$th dw=$dw x0=$x0 $h $corner: a false success: $r"; fails=$((fails + 1)) ;;
	"task: achieved"*) ;;
	*) [ "$want" = a ] && { echo "FAIL: th=$th dw=$dw x0=$x0 $h $corner: not achieved: $r"; fails=$((fails + 1)); } ;;
	esac
done <<EOC
1 5 5 north ne h
1 5 29 east sw h
1 6 5 south sw h
1 6 29 north nw h
2 5 15 east nw a
2 6 29 east nw a
3 5 15 east nw a
3 5 29 north nw a
3 6 5 south se a
EOC
[ $fails = 0 ]
