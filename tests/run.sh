#!/bin/sh
# run.sh - runs every test and prints the total: unit-test binaries, golden tests,
# malformed-input tests and the scripted checks in tests/*.test.sh.
#
#   sh tests/run.sh UTAK UNIT-BINARY...
#
# Golden tests (tests/golden/NAME.args + NAME.out [+ NAME.code]): utak is run with
# the arguments in NAME.args (shell words, read by sh), its stdout must equal
# NAME.out byte for byte and its exit status NAME.code (0 when absent). When
# NAME.svg is there too, the run also draws its picture (--svg), which must equal
# it; when NAME.replay is, it writes its replay (--html), whose data (the lines
# inside the page's utak-replay-data script) must equal it.
# Malformed input (tests/bad/NAME.w or NAME.args, + NAME.err): exit status 2,
# nothing on stdout, and stderr equal to NAME.err.
# A scripted check that exits 77 was skipped (it says why on its last line).
# Ends with "N passed, N failed" (and ", N skipped" when any were) and exits 1 when
# anything failed.
utak=$1; shift
pass=0; fail=0; skip=0
tmp=${TMPDIR:-/tmp}/utak-test.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM

ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "[FAIL] $*"; }

for bin in "$@"; do
	"$bin" >"$tmp/unit" 2>"$tmp/unit.err"; st=$?
	p=$(grep -c '^\[PASS\]' "$tmp/unit"); f=$(grep -c '^\[FAIL\]' "$tmp/unit")
	pass=$((pass + p)); fail=$((fail + f))
	grep '^\[FAIL\]' "$tmp/unit"
	if [ "$st" != 0 ] && [ "$f" = 0 ]; then
		bad "$bin: exit status $st"; sed 's/^/    /' "$tmp/unit.err" | head -n 20
	elif [ "$f" != 0 ]; then
		sed 's/^/    /' "$tmp/unit.err" | head -n 20
	fi
done

for args in tests/golden/*.args; do
	[ -f "$args" ] || continue
	name=${args%.args}
	want=0; [ -f "$name.code" ] && want=$(cat "$name.code")
	eval "set -- $(cat "$args")"
	rm -f "$tmp/svg" "$tmp/html"
	[ -f "$name.svg" ] && set -- "$@" --svg "$tmp/svg"
	[ -f "$name.replay" ] && set -- "$@" --html "$tmp/html"
	"$utak" "$@" >"$tmp/out" 2>"$tmp/err"; st=$?
	if [ "$st" != "$want" ]; then
		bad "$name: exit status $st, want $want"; head -n 5 "$tmp/err"
	elif ! cmp -s "$tmp/out" "$name.out"; then
		bad "$name: stdout differs"; diff "$name.out" "$tmp/out" | head -n 20
	elif [ -f "$name.svg" ] && ! cmp -s "$tmp/svg" "$name.svg"; then
		bad "$name: the picture differs"; diff "$name.svg" "$tmp/svg" | head -n 20
	elif [ -f "$name.replay" ] && ! sh tests/replay-data.sh "$tmp/html" | cmp -s - "$name.replay"; then
		bad "$name: the replay's data differs"; sh tests/replay-data.sh "$tmp/html" | diff "$name.replay" - | cut -c1-200 | head -n 20
	else ok; fi
done

for input in tests/bad/*.w tests/bad/*.args; do
	[ -f "$input" ] || continue
	name=${input%.*}
	case $input in
	*.w) "$utak" "$input" >"$tmp/out" 2>"$tmp/err"; st=$? ;;
	*) eval "set -- $(cat "$input")"; "$utak" "$@" >"$tmp/out" 2>"$tmp/err"; st=$? ;;
	esac
	if [ "$st" != 2 ]; then
		bad "$input: exit status $st, want 2"; head -n 3 "$tmp/err"
	elif [ -s "$tmp/out" ]; then
		bad "$input: wrote to stdout"
	elif ! cmp -s "$tmp/err" "$name.err"; then
		bad "$input: message differs"; diff "$name.err" "$tmp/err"
	else ok; fi
done

for script in tests/*.test.sh; do
	[ -f "$script" ] || continue
	UTAK="$utak" sh "$script" >"$tmp/script" 2>&1; st=$?
	if [ "$st" = 0 ]; then ok
	elif [ "$st" = 77 ]; then skip=$((skip + 1)); echo "[SKIP] $script: $(tail -n 1 "$tmp/script")"
	else bad "$script"; sed 's/^/    /' "$tmp/script" | tail -n 20; fi
done

if [ "$skip" = 0 ]; then echo "$pass passed, $fail failed"
else echo "$pass passed, $fail failed, $skip skipped"; fi
[ "$fail" = 0 ]
