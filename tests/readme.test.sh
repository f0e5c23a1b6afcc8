#!/bin/sh
# readme.test.sh - the sessions shown in README.md are what utak prints. Every line
# of a ``` block that starts with "$ ./utak" is run (with $UTAK for ./utak, from the
# top of the repository) and its output must equal the lines that follow it in the
# block, up to the next "$ " line, a blank line before one, or the end of the block.
# `make readme` rewrites them (tests/readme-update.sh); read the diff before you
# commit it.
set -u
tmp=${TMPDIR:-/tmp}/utak-readme.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT
awk -v dir="$tmp" '
	/^```/ { inblock = !inblock; n_open = 0; next }
	inblock && /^\$ \.\/utak / { n++; cf = dir "/" n ".cmd"; ef = dir "/" n ".exp"
		print substr($0, 3) > cf; close(cf); printf "" > ef; n_open = 1; blank = 0; next }
	inblock && n_open && /^$/ { blank++; next }
	inblock && n_open { while (blank > 0) { print "" >> ef; blank-- } print >> ef }
' README.md
fail=0 count=0
for cmd in "$tmp"/*.cmd; do
	[ -f "$cmd" ] || continue
	count=$((count + 1))
	exp=${cmd%.cmd}.exp
	line=$(sed 's|^\./utak|"$UTAK"|' "$cmd")
	eval "$line" >"$tmp/got" 2>&1
	if ! cmp -s "$tmp/got" "$exp"; then
		echo "README.md: \$ $(cat "$cmd"): the output differs:"
		diff "$exp" "$tmp/got" | head -n 10
		fail=1
	fi
done
[ "$count" -gt 0 ] || { echo "README.md: no sessions found"; exit 1; }
echo "$count README sessions checked"
exit $fail
