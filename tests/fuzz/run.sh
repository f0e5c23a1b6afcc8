#!/bin/sh
# run.sh - runs each fuzz harness for a bounded time and fails on any crash, leak
# or timeout (issue 6). Used by `make fuzz-run` and .ci/run.
#
#   FUZZ_SECONDS=60 sh tests/fuzz/run.sh build/fuzz/fuzz_NAME...
#
# Harness fuzz_NAME starts from the committed seeds in tests/fuzz/corpus/NAME/
# (read only) and grows its own corpus in build/fuzz/corpus/NAME/, which persists
# between runs on one machine. A crash, leak or timeout leaves its input in
# build/fuzz/artifacts/NAME/: make it a tests/bad/ case before fixing the bug.
# Limits: inputs up to FUZZ_MAX_LEN bytes (8192: past the world file's longest
# line, 4096), 10 s per input (the slowest real input takes well under 1 s),
# 2 GiB of memory. Prints one summary line per harness; exits 1 if any failed.
seconds=${FUZZ_SECONDS:-60}
max_len=${FUZZ_MAX_LEN:-8192}
status=0
for bin in "$@"; do
	name=${bin##*/fuzz_}
	work=build/fuzz/corpus/$name art=build/fuzz/artifacts/$name
	mkdir -p "$work" "$art"
	log=build/fuzz/$name.log
	seeds=tests/fuzz/corpus/$name
	[ -d "$seeds" ] || seeds=
	"$bin" -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
		-print_final_stats=1 -artifact_prefix="$art/" "$work" $seeds >"$log" 2>&1
	st=$?
	runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
	secs=$(sed -n 's/^stat::.*time.*: *//p' "$log" | head -n 1)
	cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1)
	if [ "$st" = 0 ]; then
		echo "[PASS] fuzz_$name: ${runs:-?} runs in ${seconds} s, $cov, corpus $(ls "$work" | wc -l) inputs"
	else
		status=1
		echo "[FAIL] fuzz_$name: exit status $st; input in $art/, log in $log"
		grep -E 'ERROR|SUMMARY|check failed|runtime error' "$log" | head -n 10 | sed 's/^/    /'
	fi
done
exit $status
