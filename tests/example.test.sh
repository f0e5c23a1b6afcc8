#!/bin/sh
# example.test.sh - examples/plan.c, the planner library's example (man utak-plan(3)),
# built against the in-tree library by make check and run on every 10th problem of
# the Dragon Age map arena (tests/data/movingai): its grid A* length must equal the
# published optimum, the rope-tightened path must be no longer than the skeleton path
# it came from, and both must begin at S and end at D.
cd "$(dirname "$0")/.." || exit 2
bin=${PLAN_EXAMPLE:-build/chk/examples/plan}
map=tests/data/movingai/maps/dao/arena.map
scen=tests/data/movingai/scenarios/dao/arena.map.scen
[ -x "$bin" ] || { echo "example: $bin not built"; exit 1; }
status=0 runs=0
problems=$(awk -F'\t' 'NR > 1 && NR % 10 == 2 && $9 > 0 { print $5, $6, $7, $8, $9 }' "$scen")
echo "$problems" | {
	while read -r sx sy gx gy opt; do
		out=$("$bin" "$map" "$sx" "$sy" "$gx" "$gy") || { echo "example: $sx $sy $gx $gy: exit $?"; exit 1; }
		echo "$out" | awk -v sx="$sx" -v sy="$sy" -v gx="$gx" -v gy="$gy" -v opt="$opt" '
			/^skeleton path:/ { skel = $NF }
			/^rope-tightened:/ { rope = $NF; inrope = 1; next }
			inrope && /^  \(/ { gsub(/[(),]/, ""); if (!n++) { fx = $1; fy = $2 } lx = $1; ly = $2; next }
			/^grid A\* optimum:/ { astar = $NF }
			END {
				tol = 1e-3 + 1e-5 * opt
				if (astar == "" || (astar - opt > tol || opt - astar > tol)) { print "A* " astar " != published " opt; bad = 1 }
				if (rope == "" || rope > skel + 1e-9) { print "rope " rope " longer than skeleton path " skel; bad = 1 }
				if (fx != sx + 0.5 || fy != sy + 0.5 || lx != gx + 0.5 || ly != gy + 0.5) { print "path does not join S and D"; bad = 1 }
				exit bad
			}' || { echo "example: problem $sx $sy -> $gx $gy failed"; exit 1; }
	done
} || status=1
# The manual's example (man/utak-plan.3, between its "$ ./plan" line and .EE) is
# what the program prints.
man=man/utak-plan.3
margs=$(sed -n 's/^\$ \.\/plan //p' "$man")
want=$(sed -n '/^\$ \.\/plan /,/^\.EE/p' "$man" | sed '1d;$d' | sed 's/\\-/-/g')
# shellcheck disable=SC2086
got=$("$bin" $margs)
[ -n "$margs" ] && [ "$got" = "$want" ] || { echo "example: utak-plan(3)'s example differs from the program:"; echo "$got"; status=1; }
n=$(echo "$problems" | wc -l)
[ "$n" -ge 10 ] || { echo "example: only $n problems read"; status=1; }
exit $status
