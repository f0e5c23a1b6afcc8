#!/bin/sh
# roundtrip.test.sh - `-o FILE` writes a world that utak reads back to the same
# state: after a run of motor commands, the written world's TABLE equals the
# TABLE the run ended with, square for square, and writing it again changes nothing.
set -e
tmp=${TMPDIR:-/tmp}/utak-rt.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT
script='move 3 8; grasp; push 5 0; turn 37.5; push 0 -2.25; release; move -4 -1'
for w in worlds/*.w; do
	"$UTAK" "$w" --act "$script" --dump table -o "$tmp/a.w" | sed '/^act /d' >"$tmp/a.out"
	"$UTAK" "$tmp/a.w" --dump table -o "$tmp/b.w" >"$tmp/b.out"
	cmp "$tmp/a.out" "$tmp/b.out" || { echo "$w: TABLE differs after reading back"; exit 1; }
	cmp "$tmp/a.w" "$tmp/b.w" || { echo "$w: written world differs when written again"; exit 1; }
done
