#!/bin/sh
# outputs.test.sh - what utak promises about the files it writes (output.h; README
# "Reliability"; utak(1) EXIT STATUS), tried as a careful user would:
#   - -o over the world file it read, cut short by a file-size limit (ulimit -f)
#     mid-write: exit 2, "utak: FILE: File too large", the file as it was;
#   - -o over its own input, when all goes well: the same bytes as -o elsewhere;
#   - --svg /dev/full, and standard output on /dev/full: exit 2 and one line
#     "utak: NAME: No space left on device"; with stdout lost, no output replaces
#     its target;
#   - a path that cannot be written (no such directory, a path under a regular
#     file, a directory): exit 2 before the run, nothing on standard output;
#   - a task that fails with an output that fails: 2 wins over 1; a task that fails
#     with outputs that work: 1, and the outputs are written;
#   - a replaced file keeps its permission bits, a symbolic link stays a link;
#   - '-' and /dev/stdout are standard output, the contents after the trace, even
#     when standard output is a regular file (opened anew, /dev/stdout overwrote
#     the trace from its start);
#   - killed mid-run (SIGTERM), no temporary is left and the target is untouched;
#   - no run leaves a temporary (.utak-*) behind.
tmp=${TMPDIR:-/tmp}/utak-outputs.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT INT TERM
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# no_temps WHAT: no temporary is left in $tmp.
no_temps() {
	left=$(find "$tmp" -name '.utak-*' | head -n 3)
	[ -z "$left" ] || fail "$1: temporaries left: $left"
}

# expect WHAT STATUS MESSAGE: the last run's exit status ($st) and its stderr.
expect() {
	[ "$st" = "$2" ] || fail "$1: exit status $st, want $2"
	if [ -z "$3" ]; then [ ! -s "$tmp/err" ]; else printf '%s\n' "$3" | cmp -s - "$tmp/err"; fi ||
		fail "$1: stderr '$(head -c 300 "$tmp/err")', want '$3'"
}

# A world of some 2 KB: 60 small squares in a row.
awk 'BEGIN { print "table 200 200";
	for (i = 0; i < 60; i++) printf "object o%d A %d 5 %d 5 %d 7 %d 7\n", i, 5 + 3 * i, 7 + 3 * i, 7 + 3 * i, 5 + 3 * i;
	print "utak 100.5 100.5 north" }' >"$tmp/big.w"

# -o over its own input under a 1 KiB file-size limit (dash counts ulimit -f in
# 512-byte blocks, bash in 1024: either is below the 2 KB written). Standard output
# goes to /dev/null, which no file-size limit applies to.
cp "$tmp/big.w" "$tmp/W.w"
(ulimit -f 2; exec "$UTAK" "$tmp/W.w" --act "move 1 1" -o "$tmp/W.w" >/dev/null 2>"$tmp/err"); st=$?
expect "-o over its input, ulimit -f" 2 "utak: $tmp/W.w: File too large"
cmp -s "$tmp/big.w" "$tmp/W.w" || fail "-o over its input, ulimit -f: the world file was changed"
"$UTAK" "$tmp/W.w" >/dev/null 2>&1 || fail "-o over its input, ulimit -f: the world file no longer loads"
no_temps "ulimit -f"

# -o over its own input, all well: the result is what -o elsewhere writes.
script="move 3 8; grasp; turn -20; push 1 0"
cp worlds/room.w "$tmp/room.w"
"$UTAK" worlds/room.w --act "$script" -o "$tmp/other.w" >"$tmp/out1" 2>&1 || fail "-o elsewhere: status $?"
"$UTAK" "$tmp/room.w" --act "$script" -o "$tmp/room.w" >"$tmp/out2" 2>"$tmp/err"; st=$?
expect "-o over its input" 0 ""
cmp -s "$tmp/other.w" "$tmp/room.w" || fail "-o over its input: not what -o elsewhere wrote"
cmp -s "$tmp/out1" "$tmp/out2" || fail "-o over its input: another run"

# A full device: --svg, -o and standard output.
for opt in --svg -o; do
	"$UTAK" worlds/room.w -q "go ne-corner" $opt /dev/full >"$tmp/out" 2>"$tmp/err"; st=$?
	expect "$opt /dev/full" 2 "utak: /dev/full: No space left on device"
done
echo old >"$tmp/kept.w"
"$UTAK" worlds/room.w -q "go ne-corner" -o "$tmp/kept.w" --svg "$tmp/new.svg" >/dev/full 2>"$tmp/err"; st=$?
expect "standard output on /dev/full" 2 "utak: standard output: No space left on device"
[ "$(cat "$tmp/kept.w")" = old ] || fail "standard output on /dev/full: -o replaced its target"
[ ! -e "$tmp/new.svg" ] || fail "standard output on /dev/full: --svg wrote its file"
for opt in --help --version; do
	"$UTAK" $opt >/dev/full 2>"$tmp/err"; st=$?
	expect "$opt on /dev/full" 2 "utak: standard output: No space left on device"
done
no_temps "/dev/full"

# Paths that cannot be written fail before the run: nothing on standard output.
echo text >"$tmp/regular"
for case in "-o|$tmp/nodir/x.w|No such file or directory" "--svg|$tmp/nodir/x.svg|No such file or directory" \
	"-o|$tmp/regular/x.w|Not a directory" "--svg|$tmp/regular/x.svg|Not a directory" \
	"-o|$tmp|Is a directory" "--svg|$tmp/|Is a directory"; do
	opt=${case%%|*} rest=${case#*|}; path=${rest%%|*} why=${rest#*|}
	"$UTAK" worlds/room.w "go ne-corner" "$opt" "$path" >"$tmp/out" 2>"$tmp/err"; st=$?
	expect "$opt $path" 2 "utak: $path: $why"
	[ ! -s "$tmp/out" ] || fail "$opt $path: the run went ahead ($(head -n 1 "$tmp/out"))"
done
no_temps "bad paths"

# A failed task: 1 with its outputs written, 2 when an output fails too.
"$UTAK" worlds/boxed.w -q "go square" -o "$tmp/fail.w" --svg "$tmp/fail.svg" >/dev/null 2>"$tmp/err"; st=$?
expect "failed task" 1 ""
[ -s "$tmp/fail.w" ] && [ -s "$tmp/fail.svg" ] || fail "failed task: outputs not written"
"$UTAK" worlds/boxed.w -q "go square" --svg /dev/full >/dev/null 2>"$tmp/err"; st=$?
expect "failed task and failed output" 2 "utak: /dev/full: No space left on device"

# A replaced file keeps its mode; a link stays a link, and its file is replaced.
cp worlds/room.w "$tmp/mode.w"; chmod 640 "$tmp/mode.w"
"$UTAK" "$tmp/mode.w" --act "move 1 1" -o "$tmp/mode.w" >/dev/null || fail "mode: status $?"
[ "$(stat -c %a "$tmp/mode.w")" = 640 ] || fail "mode: $(stat -c %a "$tmp/mode.w"), want 640"
ln -s mode.w "$tmp/link.w"
"$UTAK" "$tmp/link.w" --act "move 0 1" -o "$tmp/link.w" >/dev/null || fail "link: status $?"
[ -L "$tmp/link.w" ] || fail "link: the link was replaced by a file"
grep -q '^utak 21\.5 14\.5 north$' "$tmp/mode.w" || fail "link: the file it names was not written"

# Standard output as an output: the trace, then the world file, whole. The world
# part must read back as -o elsewhere writes it.
"$UTAK" worlds/room.w --act "move 1 1" -o "$tmp/std.w" >"$tmp/trace" 2>&1 || fail "stdout: reference status $?"
for o in - /dev/stdout; do
	"$UTAK" worlds/room.w --act "move 1 1" -o "$o" >"$tmp/both" 2>"$tmp/err"; st=$?
	expect "-o $o" 0 ""
	cat "$tmp/trace" "$tmp/std.w" | cmp -s - "$tmp/both" || fail "-o $o: not the trace followed by the world"
done
[ ! -e ./- ] || fail "-o -: a file named '-' was made"
"$UTAK" worlds/room.w --act "move 1 1" -o - --svg /dev/stdout >/dev/null 2>"$tmp/err"; st=$?
expect "-o - --svg /dev/stdout" 2 "utak: -o and --svg name the same file '/dev/stdout' (utak --help for usage)"

# SIGTERM while an output is open: the --svg FIFO has no reader, so utak waits in
# opening it, after -o's temporary exists; killed there, it leaves nothing.
mkfifo "$tmp/fifo"
"$UTAK" worlds/room.w --act "move 1 1" -o "$tmp/term.w" --svg "$tmp/fifo" >/dev/null 2>&1 &
pid=$!
i=0
while [ -z "$(find "$tmp" -name '.utak-*')" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
[ $i -lt 100 ] || fail "SIGTERM: no temporary appeared while -o was open"
kill -TERM $pid; wait $pid; st=$?
[ "$st" = 143 ] || fail "SIGTERM: exit status $st, want 143"
[ ! -e "$tmp/term.w" ] || fail "SIGTERM: -o's target was written"
no_temps "SIGTERM"

[ $fails = 0 ]
