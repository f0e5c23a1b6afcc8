#!/bin/sh
# step.test.sh - `--step` prints what -v prints (every dump after each cycle) and
# waits for a line on standard input before the first cycle and after each one,
# saying so on stderr; "q", or the end of the input, lets the run go on to its end.
set -e
tmp=${TMPDIR:-/tmp}/utak-step.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT
prompt="-- Enter: the next cycle; q: run to the end --"
"$UTAK" -v worlds/room.w "go ne-corner" >"$tmp/verbose"
# Two Enters, then the end of the input: three waits (the start, cycles 1 and 2).
printf '\n\n' | "$UTAK" --step worlds/room.w "go ne-corner" >"$tmp/step" 2>"$tmp/err"
cmp -s "$tmp/verbose" "$tmp/step" || { echo "--step printed other than -v"; diff "$tmp/verbose" "$tmp/step" | head; exit 1; }
[ "$(grep -cx -- "$prompt" "$tmp/err")" = 3 ] || { echo "waits: $(grep -c . "$tmp/err"), want 3"; exit 1; }
# q at the first wait: one wait, and the run to its end.
printf 'q\n\n\n\n' | "$UTAK" --step worlds/room.w "go ne-corner" >"$tmp/step" 2>"$tmp/err"
cmp -s "$tmp/verbose" "$tmp/step" && [ "$(grep -cx -- "$prompt" "$tmp/err")" = 1 ] || { echo "q: did not stop waiting"; exit 1; }
# The dumps named by --dump, and only those.
printf '' | "$UTAK" --step --dump retina worlds/room.w "go ne-corner" >"$tmp/step" 2>/dev/null
[ "$(grep -c '^retina, ahead at the top:' "$tmp/step")" = "$(($(grep -c '^cycle ' "$tmp/step") + 1))" ] &&
	! grep -q '^world model:' "$tmp/step" || { echo "--step --dump retina: not one retina a cycle"; exit 1; }
