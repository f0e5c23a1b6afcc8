#!/bin/sh
# readme-update.sh - rewrites the sessions in README.md with what ./utak prints
# now (see readme.test.sh for what a session is). A deliberate act, like
# regenerating golden files: read `git diff README.md` before you commit it.
set -eu
utak=${1:-./utak}
tmp=${TMPDIR:-/tmp}/utak-readme-update.$$
trap 'rm -f "$tmp"' EXIT
: >"$tmp"
inblock=0 skipping=0 blank=0
while IFS= read -r line || [ -n "$line" ]; do
	case "$line" in
	'```'*)
		inblock=$((1 - inblock)); skipping=0; blank=0
		printf '%s\n' "$line" >>"$tmp"; continue ;;
	esac
	if [ "$inblock" = 1 ]; then
		case "$line" in
		'$ ./utak '*)
			while [ "$blank" -gt 0 ]; do echo >>"$tmp"; blank=$((blank - 1)); done
			printf '%s\n' "$line" >>"$tmp"
			cmd=$(printf '%s\n' "${line#\$ }" | sed "s|^\./utak|$utak|")
			sh -c "$cmd" >>"$tmp" 2>&1 || true
			skipping=1; blank=0; continue ;;
		'')
			# a blank line ends a session's output only when another follows
			[ "$skipping" = 1 ] && { blank=$((blank + 1)); continue; } ;;
		'$ '*) ;;
		*) [ "$skipping" = 1 ] && [ "$blank" = 0 ] && continue ;;
		esac
		if [ "$skipping" = 1 ] && [ "$blank" -gt 0 ]; then
			# the blank lines between two sessions
			while [ "$blank" -gt 0 ]; do echo >>"$tmp"; blank=$((blank - 1)); done
			skipping=0
		fi
	fi
	printf '%s\n' "$line" >>"$tmp"
done <README.md
cp "$tmp" README.md
git diff --stat README.md 2>/dev/null || true
