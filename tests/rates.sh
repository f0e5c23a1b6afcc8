#!/bin/sh
# rates.sh - tasks (i)-(v) on worlds nobody tuned for (issue 13, "Tests"): how often
# each is achieved, and how often Utak's belief and the judge's verdict differ.
#
#   GEN=DIR sh tests/rates.sh UTAK MODE...      MODE: random, perturb, noise
#
#   random   RATES_RANDOM (300) worlds of tests/gen/worldgen.c (seeds 1...), each
#            with one of the tasks (i)-(v) in turn
#   perturb  every world in worlds/ shifted by tests/gen/perturb.c (objects up to two
#            squares, Utak's heading turned), RATES_PERTURB (4) copies each, every task
#   noise    every world in worlds/ with --noise 0.05, RATES_SEEDS (10) seeds, every task
#
# A run is "not applicable" when the judge says the task does not apply (there is no
# such object, no next room, no corner to push round, or the true world's walls make
# it impossible: judge.h). Per task it prints the runs,
# those that apply, the achieved rate among them, the belief/verdict disagreements
# and, counted apart, the false successes (Utak sure of a task the judge says is not
# done, counted in runs where the task does not apply too). With RATES_TARGETS naming a mode (or "all") the issue's target for it is
# checked: perturb, every applicable run achieved; random, disagreement under 3% and
# no false success; noise, at least 90% achieved. Runs go RATES_JOBS (2) at a time.
# RATES_KEEP=FILE appends every run's line ("MODE|TASK|STATUS|LAST LINE|WORLD
# OPTIONS") to FILE, to find the runs behind a figure; the generated worlds are
# kept beside it in FILE.worlds/.
set -u
UTAK=$1; shift
GEN=${GEN:-build/rel/gen}
JOBS=${RATES_JOBS:-2}
TARGETS=${RATES_TARGETS:-}
CYCLES=${RATES_CYCLES:-300}
tmp=${TMPDIR:-/tmp}/utak-rates.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT
TASKS="go ne-corner|go next-room|go square|go round square|push square ne-corner"
status=0

# run_list LIST: each line "WORLD|TASK|OPTIONS" run, one result line each in
# $tmp/res: "TASK|STATUS|LAST LINE".
run_list()
{
	: >"$tmp/res"
	n=0
	while IFS='|' read -r world task opts; do
		n=$((n + 1))
		printf '%s\0' "$n|$world|$task|$opts"
	done <"$1" | xargs -0 -P "$JOBS" -n 1 sh -c '
		IFS="|" read -r n world task opts <<EOT
$1
EOT
		# shellcheck disable=SC2086
		"$0" -q --max-cycles '"$CYCLES"' $opts "$world" "$task" >"'"$tmp"'/o.$n" 2>&1
		st=$?
		printf "%s|%s|%s|%s\n" "$task" "$st" "$(tail -n 1 "'"$tmp"'/o.$n")" "$world $opts" >"'"$tmp"'/r.$n"
		rm -f "'"$tmp"'/o.$n"' "$UTAK"
	cat "$tmp"/r.* >"$tmp/res" 2>/dev/null
	rm -f "$tmp"/r.*
}

# report NAME: the figures of $tmp/res, per task and in all (report.awk below);
# checks NAME's target when RATES_TARGETS names it.
report()
{
	awk -F'|' -v name="$1" -v targets="$TARGETS" -v tasks="$TASKS" -f "$tmp/report.awk" <"$tmp/res" || status=1
}

cat >"$tmp/report.awk" <<'EOA'
BEGIN { nt = split(tasks, order, "|") }
function add(t, st, last) {
	runs[t]++
	# A false success counts even where the task does not apply: Utak sure he
	# touched the square in a world the judge finds none in is the worst case.
	if (last ~ /Utak believes it achieved/) fs[t]++
	if (last ~ /does not apply|there is no /) { na[t]++; return }
	app[t]++
	if (st == 0 && last ~ /^task: achieved/) ok[t]++
	if (last ~ /Utak believes it/) dis[t]++
}
{ add($1, $2, $3); add("all", $2, $3); if ($2 != 0 && $2 != 1) print "  exit " $2 ": " $4 ": " $3 }
END {
	printf "%s:\n", name
	printf "  %-22s %5s %6s %9s %9s %6s\n", "task", "runs", "apply", "achieved", "disagree", "false"
	for (i = 1; i <= nt + 1; i++) {
		t = i <= nt ? order[i] : "all"
		if (!(t in runs)) continue
		a = app[t] + 0
		printf "  %-22s %5d %6d %8.1f%% %8.1f%% %6d\n", t, runs[t], a,
			a ? 100 * ok[t] / a : 0, a ? 100 * dis[t] / a : 0, fs[t] + 0
	}
	a = app["all"] + 0
	fail = 0
	if (index(targets, name) || index(targets, "all")) {
		if (name == "perturb" && ok["all"] < a) { print "  target unmet: every applicable run achieved"; fail = 1 }
		if (name == "random" && (dis["all"] >= 0.03 * a || fs["all"] > 0)) { print "  target unmet: under 3% disagreement, no false success"; fail = 1 }
		if (name == "noise" && ok["all"] < 0.9 * a) { print "  target unmet: at least 90% achieved"; fail = 1 }
	}
	exit fail
}
EOA

for mode in "$@"; do
	: >"$tmp/list"
	case "$mode" in
	random)
		mkdir -p "$tmp/g"
		"$GEN/worldgen" -n "${RATES_RANDOM:-300}" -o "$tmp/g" 1 || exit 2
		i=0
		for w in $(ls "$tmp"/g/*.w | sort -V); do
			t=$(echo "$TASKS" | cut -d'|' -f$((i % 5 + 1))); i=$((i + 1))
			echo "$w|$t|" >>"$tmp/list"
		done ;;
	perturb)
		mkdir -p "$tmp/p"
		"$GEN/perturb" -n "${RATES_PERTURB:-4}" -o "$tmp/p" 1 worlds/*.w || exit 2
		for w in "$tmp"/p/*.w; do
			echo "$TASKS" | tr '|' '\n' | while read -r t; do echo "$w|$t|" >>"$tmp/list"; done
		done ;;
	noise)
		for w in worlds/*.w; do
			s=1
			while [ "$s" -le "${RATES_SEEDS:-10}" ]; do
				echo "$TASKS" | tr '|' '\n' | while read -r t; do echo "$w|$t|--noise 0.05 --seed $s" >>"$tmp/list"; done
				s=$((s + 1))
			done
		done ;;
	*) echo "rates.sh: unknown mode $mode" >&2; exit 2 ;;
	esac
	run_list "$tmp/list"
	if [ -n "${RATES_KEEP:-}" ]; then
		mkdir -p "$RATES_KEEP.worlds"
		for d in g p; do
			[ -d "$tmp/$d" ] && cp -r "$tmp/$d" "$RATES_KEEP.worlds/"
		done
		awk -v m="$mode" -v t="$tmp/" -v k="$RATES_KEEP.worlds/" \
			'{ while ((i = index($0, t)) > 0) $0 = substr($0, 1, i - 1) k substr($0, i + length(t)); print m "|" $0 }' \
			"$tmp/res" | sort -t'|' -k5 -V >>"$RATES_KEEP"
	fi
	report "$mode"
done
exit $status
