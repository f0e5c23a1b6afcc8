#!/bin/sh
# replay.test.sh - `--html FILE` writes one self-contained page that replays the run.
#
# Without a browser: the page's data is JSON with one frame per cycle printed plus
# the start, each frame's trace line the one utak printed for that cycle; the page
# names no external resource; every frame's world model, however the page wrote it,
# is the one `-v --dump model` printed for that cycle; a TABLE of 4096 x 4096 costs
# a page of the same order as a small one (its size grows with the run, not the
# TABLE's area); in a carry
# that turns (worlds/lshape-turn.w), every trace line whole, plan lines too, and the
# held object's planned poses are the printed plan's pushes and turns; an --act run
# has a frame per command; a page that cannot be written is exit status 2 and one
# line "utak: FILE: reason".
# In a browser (tests/browser/replay.mjs, headless Chromium driven by
# playwright-core): the page of the paper's task (v) in worlds/room.w loads with no
# console error and no request, steps cycle by cycle (each with its trace line and
# the objects believed then, as the data has them), plays, and its TABLE differs
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

# The world model of every frame against the one utak dumps for that cycle (-v
# --dump model): each node's rings, vertex by vertex, however the page wrote them
# (whole, as the index of the same node a frame before, or as the changes to it).
# The page leaves out the floor's holes that are objects' outlines: its rings must
# be the dump's in order, some skipped, an object's all of them.
"$UTAK" -v --dump model --html "$tmp/dump.html" worlds/room.w "push square ne-corner" >"$tmp/dump.txt"
sh tests/replay-data.sh "$tmp/dump.html" >"$tmp/dump.json"
python3 - "$tmp/dump.json" "$tmp/dump.txt" <<'PY'
import json, re, sys
d = json.load(open(sys.argv[1]))
dumps, node, ring = [], None, None
for l in open(sys.argv[2]):
    if l.startswith("world model: "): dumps.append({})
    elif m := re.match(r"\s*node \d+ (\S+) ", l):
        node = [] if m.group(1) == "$org" else dumps[-1].setdefault(m.group(1), [])
    elif m := re.match(r"\s*(boundary|hole) \d+ vertices:", l):
        ring = {"hole": m.group(1) == "hole", "v": [], "beyond": ""}
        node.append(ring)
    elif m := re.match(r"\s*\((\S+), (\S+)\) conf \S+, segment conf (\S+) beyond (\w)", l):
        ring["v"].append([float(m.group(1)), float(m.group(2)), float(m.group(3))])
        ring["beyond"] += m.group(4)  # o(ccupied), u(nknown), f(loor)
assert len(dumps) == len(d["frames"]), (len(dumps), len(d["frames"]))
before, nodes, spliced = [], [], 0
def same_ring(a, b):
    return a["hole"] == b["hole"] and len(a["v"]) == len(b["v"]) and a["beyond"] == b["beyond"] and all(
        abs(p[0] - q[0]) < 0.006 and abs(p[1] - q[1]) < 0.006 and abs(p[2] - q[2]) < 0.051 for p, q in zip(a["v"], b["v"]))
for k, f in enumerate(d["frames"]):
    if "model" in f:
        nodes = []
        for n in f["model"]["nodes"]:
            if isinstance(n, int): n = before[n]
            elif "like" in n:
                spliced += 1
                like = before[n["like"]]
                for r in n["rings"]:
                    if "from" in r:
                        o, p, q = like["rings"][r["from"][0]], r["from"][1], r["from"][2]
                        r["v"] = o["v"][:p] + r["v"] + o["v"][len(o["v"]) - q:]
                        r["beyond"] = o["beyond"][:p] + r["beyond"] + o["beyond"][len(o["beyond"]) - q:]
            nodes.append(n)
        before = nodes
    assert sorted(n["name"] for n in nodes) == sorted(dumps[k]), (k, [n["name"] for n in nodes], list(dumps[k]))
    for n in nodes:
        want, i = dumps[k][n["name"]], 0
        for r in n["rings"]:
            while i < len(want) and not same_ring(r, want[i]):
                assert n["kind"] == "floor", (k, n["name"], "a ring differs")
                i += 1
            assert i < len(want), (k, n["name"], "a ring not in the dump")
            i += 1
        assert n["kind"] == "floor" or i == len(want), (k, n["name"], "rings missing")
assert spliced > 20, spliced
PY

# A carry that turns (task (ix)): each cycle's trace line is all utak printed for it,
# the structured plan's lines too; a frame holding the object has its planned poses,
# and from pose to pose they are the commands of the plan printed last (a push moves
# the pose by its vector, a turn turns it about Utak's point by its degrees).
"$UTAK" --html "$tmp/carry.html" worlds/lshape-turn.w "push lshape next-room" >"$tmp/carry.txt"
sh tests/replay-data.sh "$tmp/carry.html" >"$tmp/carry.json"
python3 - "$tmp/carry.json" "$tmp/carry.txt" <<'PY'
import json, re, sys
d = json.load(open(sys.argv[1]))
blocks = []
for l in open(sys.argv[2]).read().splitlines():
    if re.match(r"cycle \d+: ", l): blocks.append(l)
    elif blocks and l.startswith("  "): blocks[-1] += "\n" + l  # the cycle's plan
    elif blocks: break  # the TABLE at the end
assert len(d["frames"]) == len(blocks) + 1, (len(d["frames"]), len(blocks))
plan, checked, turned = None, 0, False
for k, block in enumerate(blocks, 1):
    assert d["frames"][k]["line"] == block, (k, d["frames"][k]["line"], block)
    m = re.search(r"carry: ([^(]*)\(", block)
    if m:
        plan = []
        for cmd in m.group(1).split(";"):
            w = cmd.split()
            if w and w[0] == "push": plan.append((float(w[1]), float(w[2]), 0.0))
            elif w and w[0] == "turn": plan.append((0.0, 0.0, float(w[1])))
    f = d["frames"][k]
    if "carry" not in f or d["frames"][k]["phase"] != "push": continue
    poses = f["carry"]["poses"]
    steps = [(b[0] - a[0], b[1] - a[1], b[2] - a[2]) for a, b in zip(poses[1:], poses[2:])]
    assert plan and len(steps) < len(plan), (k, poses, plan)
    want = plan[len(plan) - len(steps):]
    assert all(abs(x - y) < 0.02 for s, t in zip(steps, want) for x, y in zip(s, t)), (k, steps, want)
    checked += 1
    turned = turned or any(s[2] != 0 for s in steps)
assert checked >= 3 and turned, (checked, turned)
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
