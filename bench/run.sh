#!/bin/sh
# run.sh - `make bench`: the path-finding benchmark (paper 4.1 and 5) over every
# Moving AI map in ../shared/data/movingai when that data set sits beside the
# checkout, else over the few copies in tests/data/movingai (MOVINGAI=DIR chooses);
# the first line says which. The sections that need the large maps (Boston_0_1024
# and the 512 x 512 sets) say so and are skipped when the data lacks them.
#
# Prints five tables: (1) per scenario file, grid A* against the published optima
# (a check: any miss makes this script fail), the visibility-graph any-angle optimum
# (on every map with at most VISIBILITY_MAX_VERTICES corners: all of them here),
# the rope-tightened A* path, and the skeleton planner (distance transform,
# skeleton, pathgraph, query, its path before and after rope-tightening), with
# times and expansions; (2) grid A* corner to corner on the 1024 x 1024 maps
# (Boston, and the three 512 x 512 maps enlarged twice), the figure the issue
# compares with libtcod; (3) configuration-space erosion times; (4) skelbench: the
# distance transform, skeleton, pathgraph and a corner-to-corner query on synthetic
# rooms, random rectangles and a maze of 1024 to 4096 cells a side (linear growth)
# and on Boston_0_1024, then (--scaling) each job's ns a cell from 256 to 4096 beside
# the machine's floor, one read pass over the grid's bytes and over a 4-byte array;
# (5) tablebench: loading a 4096 x 4096 TABLE; (6) costbench:
# a move of 10^6 squares into the verge against one of 10, and the verdict of a
# shape task against a corner task's, on 4096 objects (issue 14).
# PATHBENCH_SAMPLE scenarios of each file, evenly spaced, are run, so the whole
# takes about a minute and a half of CPU, two and a half of wall time on the shared
# 2-core machine (most of it building the visibility graphs of Boston_0_1024 and
# random512-10-0, and skelbench's 4096 x 4096 grids).
set -u
if [ -n "${MOVINGAI:-}" ]; then data=$MOVINGAI
elif [ -d ../shared/data/movingai/maps ]; then data=../shared/data/movingai
else data=tests/data/movingai; fi
echo "Moving AI data: $data"
bin=${PATHBENCH:-build/rel/bench/pathbench}
benchdir=$(dirname "$bin")
sample=${PATHBENCH_SAMPLE:-400}
if [ ! -d "$data/maps" ] || [ ! -d "$data/scenarios" ]; then
	echo "bench/run.sh: $data: no Moving AI data (maps/ and scenarios/)" >&2
	exit 2
fi

# Pair every .scen with its map: the map named in its first problem line, found by
# file name under maps/. Sorted, so the table's order is fixed.
pairs=
for scen in $(find "$data/scenarios" -name '*.scen' | LC_ALL=C sort); do
	name=$(awk -F'\t' 'NR == 2 { n = split($2, p, "/"); print p[n]; exit }' "$scen")
	map=$(find "$data/maps" -name "$name" | LC_ALL=C sort | head -n 1)
	if [ -z "$map" ]; then
		echo "bench/run.sh: $scen: map $name not found under $data/maps" >&2
		exit 2
	fi
	pairs="$pairs $map $scen"
done

echo "== pathbench --table --sample $sample (medians per file; times in ms, one thread)"
# shellcheck disable=SC2086
"$bin" --table --sample "$sample" $pairs; st=$?
echo
boston=$data/maps/cities/Boston_0_1024.map
large="$data/maps/rooms/8room_000.map $data/maps/mazes/maze512-1-0.map $data/maps/random/random512-10-0.map"
have_large=1
for m in $boston $large; do [ -f "$m" ] || have_large=0; done
echo "== grid A* corner to corner on 1024 x 1024 maps"
if [ $have_large = 1 ]; then
	"$bin" --corner "$boston" || st=1
	# shellcheck disable=SC2086
	"$bin" --corner --scale 2 $large | tail -n +3 || st=1
	echo "== the same by the jump-point search (gridpath's GRIDPATH_JUMP)"
	"$bin" --corner --jump "$boston" | tail -n +2 || st=1
	# shellcheck disable=SC2086
	"$bin" --corner --jump --scale 2 $large | tail -n +3 || st=1
	echo
	echo "== configuration-space erosion"
	# shellcheck disable=SC2086
	"$bin" --cspace "$boston" $large || st=1
else
	echo "skipped, with the configuration-space erosion: $data lacks Boston_0_1024 and the 512 x 512 maps"
fi
echo
echo "== skelbench 3 4096: skeleton planner on synthetic grids (and Boston_0_1024 when present; CPU ms)"
if [ -f "$boston" ]; then "$benchdir/skelbench" 3 4096 "$boston" || st=1
else "$benchdir/skelbench" 3 4096 || st=1; fi
echo
echo "== skelbench --scaling 7: ns a cell of each job from 256 to 4096 beside the read passes (issue 16)"
"$benchdir/skelbench" --scaling 7 || st=1
echo
echo "== tablebench: a 4096 x 4096 TABLE with 200 objects"
"$benchdir/tablebench" || st=1
echo "== tablebench: the largest TABLE (8192 x 4096) with the most walls (4096)"
"$benchdir/tablebench" limits || st=1
echo
echo "== costbench: a motor command and a verdict cost what they do (1024 x 1024, 4096 objects)"
"$benchdir/costbench" || st=1
exit $st
