#!/bin/sh
# replay.test.sh - `--html FILE` writes one self-contained page that replays the run.
#
# Without a browser: the page's data is JSON with one frame per cycle printed plus
# the start, each frame's trace line the one utak printed for that cycle; the page
# names no external resource; a TABLE of 4096 x 4096 costs a page of the same order
# as a small one (its size grows with the run, not the TABLE's area); an --act run
# has a frame per command; a page that cannot be written is exit status 2 and one
# line "utak: FILE: reason".
# In a browser (tests/browser/replay.mjs, headless Chromium driven by
# playwright-core): the page of the paper's task (v) in worlds/room.w loads with no
# console error and no request, steps cycle by cycle, plays, and its TABLE differs
# between the first and last frame where Utak started and ended. Without chromium or
# the node module this part is skipped (exit 77), saying so, except in CI (CI set),
# where it fails: .ci/run installs both (make browser-deps).
set -e
tmp=${TMPDIR:-/tmp}/utak-replay.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT

# The page's data against what the run printed.
"$UTAK" --html "$tmp/room.html" worlds/room.w "push square ne-corner" >"$tmp/room.txt"
sh tests/replay-data.sh "$tmp/room.html" >"$tmp/room.json"
python3 - "$tmp/room.json" "$tmp/room.txt" "$tmp/room.html" <<'PY'
import json, re, sys
d = json.load(open(sys.argv[1]))
printed = [l.rstrip("\n") for l in open(sys.argv[2]) if re.match(r"cycle \d+: ", l)]
page = open(sys.argv[3]).read()
assert d["format"] == "utak-replay 1"
assert len(d["frames"]) == len(printed) + 1, (len(d["frames"]), len(printed))
assert d["cycles"] == len(printed)
for k, line in enumerate(printed, 1):
    assert d["frames"][k]["line"] == line, (k, d["frames"][k]["line"], line)
    assert d["frames"][k]["cycle"] == k
assert d["verdict"] == open(sys.argv[2]).read().splitlines()[-1]
for f in d["frames"]:
    assert len(f["retina"]) == 160 and len(f["touch"]) == 8
assert len(d["eye"]) == 160 and sum(c[2] ** 2 for c in d["eye"]) == 32 * 32
# Every plan a frame names exists; a push has planned poses of what it carries.
for f in d["frames"]:
    assert -1 <= f["plan"] < len(d["plans"])
assert any("carry" in f for f in d["frames"]), "no carried poses in a push"
# Self-contained: no external script, style sheet, font, image or fetch.
for bad in ("<script src", "<link", "@import", "url(http", "fetch(", "XMLHttpRequest", "src=\"http"):
    assert bad not in page, bad
PY

# A large TABLE: the page grows with the run, not the TABLE's area.
{
	echo "table 4096 4096"
	echo "object square A 2040 2050 2044 2050 2044 2054 2040 2054"
	echo "object brick C 2060 2040 2069 2040 2069 2043 2060 2043"
	echo "utak 2050.5 2045.5 north"
} >"$tmp/big.w"
"$UTAK" -q --max-cycles 10 --html "$tmp/big.html" "$tmp/big.w" "go square" >/dev/null || true
"$UTAK" -q --max-cycles 10 --html "$tmp/small.html" worlds/room.w "go square" >/dev/null || true # 10 cycles: the page, not the task
big=$(wc -c <"$tmp/big.html"); small=$(wc -c <"$tmp/small.html")
echo "page sizes: TABLE 4096 x 4096 $big bytes, room.w $small bytes"
[ "$big" -lt $((4 * small)) ] || { echo "a TABLE of 16 million squares made a page of $big bytes"; exit 1; }

# An --act run: a frame per command.
"$UTAK" --html "$tmp/act.html" --act "move 3 0; move 0 3; move -2 -2" worlds/room.w >/dev/null
[ "$(sh tests/replay-data.sh "$tmp/act.html" | grep -c '^{"cycle": ')" = 4 ] || { echo "--act: not 4 frames"; exit 1; }

# A page that cannot be written.
st=0; "$UTAK" -q --html /dev/full worlds/room.w "go ne-corner" >/dev/null 2>"$tmp/err" || st=$?
[ "$st" = 2 ] && [ "$(cat "$tmp/err")" = "utak: /dev/full: No space left on device" ] ||
	{ echo "/dev/full: status $st, $(cat "$tmp/err")"; exit 1; }
st=0; "$UTAK" -q --html "$tmp/no/such/dir.html" worlds/room.w "go ne-corner" >/dev/null 2>"$tmp/err" || st=$?
[ "$st" = 2 ] && [ "$(cat "$tmp/err")" = "utak: $tmp/no/such/dir.html: No such file or directory" ] ||
	{ echo "missing folder: status $st, $(cat "$tmp/err")"; exit 1; }

# In a browser.
chromium=${CHROMIUM:-/usr/bin/chromium}
why=
[ -x "$chromium" ] || why="no chromium at $chromium"
command -v node >/dev/null || why="${why:+$why; }no node"
[ -d tests/browser/node_modules/playwright-core ] || why="${why:+$why; }no playwright-core in tests/browser/node_modules"
if [ -n "$why" ]; then
	if [ -n "$CI" ]; then echo "the browser test cannot run in CI: $why (make browser-deps installs them)"; exit 1; fi
	echo "the browser part was skipped: $why (make browser-deps installs them)"
	exit 77
fi
CHROMIUM=$chromium node tests/browser/replay.mjs "$tmp/room.html" "$tmp/room.txt" ""
