#!/bin/sh
# gen.sh - writes the malformed inputs too big to commit: one past each count and
# size limit of man utak.5 LIMITS and act.h (issue 6). Run by `make check` before
# the tests; the tests/bad/*.args cases that name build/gen/ read them.
#
#   sh tests/bad/gen.sh DIR
#
# Each input is exactly one past its limit, so that the limit, not something else,
# is what fails: 4097 objects, 4097 walls, a file of 16 MiB + 1 byte, 10001 motor
# commands. (act.h's 1 MiB script cannot be passed as one argument: Linux caps an
# argument at 128 KiB; test_invariants.c checks that limit on act_parse directly.)
set -e
dir=${1:-build/gen}
mkdir -p "$dir"

# 4097 objects, each a small triangle with its own name, in a TABLE big enough
# that they do not overlap (the count is checked first, as the file is read).
awk 'BEGIN {
	print "table 1000 1000"
	for (i = 0; i < 4097; i++) {
		x = 2 + (i % 64) * 15; y = 2 + int(i / 64) * 15
		printf "object o%d A %d %d %d %d %d %d\n", i, x, y, x + 2, y, x, y + 2
	}
	print "utak 999.5 999.5 north"
}' >"$dir/objects-4097.w"

awk 'BEGIN {
	print "table 100 100"
	for (i = 0; i < 4097; i++) print "wall 10 10 20 10 20 20"
	print "utak 50.5 50.5 north"
}' >"$dir/walls-4097.w"

# A valid world padded with comment lines to 16 MiB + 1 byte.
awk 'BEGIN {
	head = "table 20 20\nutak 5.5 5.5 north\n"
	printf "%s", head
	line = "#"; for (i = 1; i < 1023; i++) line = line "x"
	n = 16777217 - length(head)
	while (n >= 1024) { print line; n -= 1024 }
	s = ""; for (i = 0; i < n - 1; i++) s = s "#"
	print s
}' >"$dir/file-16mib.w"

awk 'BEGIN { for (i = 0; i < 10001; i++) printf "grasp;"; printf "\n" }' >"$dir/act-10001.txt"
