#!/bin/sh
# doors.test.sh - the simplest two-room worlds (doorsure.h; paper 2.3 task (i)): a
# 40 x 30 TABLE cut by one wall across at row 18 with a door. Each case below was
# a false success at 49e82b6 (Utak sure of the corner, the judge: in the next room,
# or short of the corner of the one room the judge counts); the simulator's judge
# is the oracle. None may end "(Utak believes it achieved)" with the judge saying
# failed (each now ends in his doubt: the judge says failed, he does not claim).
# And the rule is no blanket doubt: the cases marked a, achieved and claimed at
# 49e82b6, stay achieved and claimed.
# Case: THICKNESS DOOR-WIDTH DOOR-X HEADING CORNER [a].
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
	*"believes it not"*|"task: failed"*) [ "$want" = a ] && { echo "FAIL: th=$th dw=$dw x0=$x0 $h $corner: not claimed: $r"; fails=$((fails + 1)); } ;;
	esac
done <<EOC
1 5 5 north ne
1 5 29 east sw
1 6 5 south sw
1 6 29 north nw
2 5 15 east nw
2 6 29 east nw
3 5 15 east nw
3 5 29 north nw
3 6 5 south se
1 3 5 north ne a
1 4 29 south ne a
2 4 15 south ne a
2 6 15 west sw a
3 3 29 west ne a
3 5 5 west se a
3 6 29 north sw a
EOC
[ $fails = 0 ]
