#!/bin/sh
# tests/noise-rate.sh [UTAK] - how often tasks (i)-(v) are achieved under noisy
# motion (paper 3.5; issue 13): --noise 0.05 over seeds 1..10 on every world in
# worlds/ where the task applies (where it is achieved without noise), for one task
# of each kind: go ne-corner, go next-room, go square, go round square, push square
# ne-corner. Prints each failing run, the rate per task and overall. Not part of
# make check (about half a minute with the release build); run by hand:
#   make && sh tests/noise-rate.sh
utak=${1:-./utak}
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT INT TERM
for t in "go ne-corner" "go next-room" "go square" "go round square" "push square ne-corner"; do
	for w in worlds/*.w; do
		"$utak" -q "$w" "$t" >/dev/null 2>&1 || continue
		for s in 1 2 3 4 5 6 7 8 9 10; do
			if "$utak" -q --noise 0.05 --seed "$s" "$w" "$t" >/dev/null 2>&1; then
				echo "$t|ok" >>"$tmp"
			else
				echo "$t|failed" >>"$tmp"
				echo "failed: $w \"$t\" --seed $s"
			fi
		done
	done
done
awk -F'|' '{ n[$1]++; if ($2 == "ok") ok[$1]++; N++; if ($2 == "ok") OK++ }
	END {
		for (t in n) printf "%-24s %3d of %3d achieved (%.0f%%)\n", t, ok[t], n[t], 100 * ok[t] / n[t]
		printf "%-24s %3d of %3d achieved (%.1f%%)\n", "all", OK, N, 100 * OK / N
	}' "$tmp" | sort
