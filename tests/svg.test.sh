#!/bin/sh
# svg.test.sh - `--svg FILE` writes a picture that explains itself: a well-formed
# SVG document (parsed as XML, root <svg> in the SVG namespace) with a title naming
# the task and the verdict (the verdict line utak printed), a legend, the TABLE, the
# trail, the start and Utak; every element inside the view box (each shape's
# coordinates, and each text's extent at the monospace advance the drawing assumes);
# one outline per object in Utak's final world model (the --dump model after the
# last cycle is the oracle), drawn once, and no $floor hole that repeats one; the
# pathgraph's edges drawn as well as its vertices; and the route drawn after (over)
# the trail. The tasks cover a push (a held object), rooms, and a planner without a
# skeleton.
set -e
tmp=${TMPDIR:-/tmp}/utak-svg.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT
n=0
for run in "room|push square ne-corner|skeleton" "tworooms|go next-room|skeleton" "clutter|go square|skeleton" \
	"room|go ne-corner|grid" "south|go round square|skeleton"; do
	w=${run%%|*}; rest=${run#*|}; task=${rest%%|*}; planner=${rest#*|}
	n=$((n + 1))
	"$UTAK" -v --dump model --planner "$planner" --svg "$tmp/$n.svg" "worlds/$w.w" "$task" >"$tmp/$n.txt" || true
	python3 - "$tmp/$n.svg" "$tmp/$n.txt" "$planner" <<'PY'
import re, sys
import xml.etree.ElementTree as ET
svg, txt, planner = sys.argv[1], open(sys.argv[2]).read(), sys.argv[3]
root = ET.parse(svg).getroot()
ns = "{http://www.w3.org/2000/svg}"
assert root.tag == ns + "svg", root.tag
ids = {e.get("id"): e for e in root.iter() if e.get("id")}
for want in ("title", "legend", "table", "model", "floor-edge", "trail", "start", "utak"):
    assert want in ids, "no element with id " + want
verdict = txt.rstrip("\n").splitlines()[-1]
task = re.search(r"^task: ([^,]*),", txt, re.M).group(1)
title = root.find(ns + "title").text
assert task in title and verdict in title, title
shown = [t.text for t in ids["title"].iter(ns + "text")]
assert any(task in s for s in shown) and verdict in shown, shown
legend = [t.text for t in ids["legend"].iter(ns + "text")]
assert "path taken" in legend and "believed object" in legend and "start" in legend, legend

# Every element inside the view box.
x0, y0, vw, vh = (float(v) for v in root.get("viewBox").split())
def inside(x, y, what):
    assert x0 - 0.01 <= x <= x0 + vw + 0.01 and y0 - 0.01 <= y <= y0 + vh + 0.01, (what, x, y, vw, vh)
def numbers(s):
    return [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", s)]
count = 0
for e in root.iter():
    tag = e.tag.replace(ns, "")
    if tag == "rect" and e.get("width") != "100%":
        x, y, w, h = (float(e.get(k)) for k in ("x", "y", "width", "height"))
        inside(x, y, tag); inside(x + w, y + h, tag)
    elif tag == "circle":
        cx, cy, r = (float(e.get(k)) for k in ("cx", "cy", "r"))
        inside(cx - r, cy - r, tag); inside(cx + r, cy + r, tag)
    elif tag == "line":
        inside(float(e.get("x1")), float(e.get("y1")), tag); inside(float(e.get("x2")), float(e.get("y2")), tag)
    elif tag in ("polyline", "path") and (e.get("points") or e.get("d")):
        v = numbers(e.get("points") or e.get("d"))
        if e.get("d", "").startswith("M0,0"):  # the arrow marker's own frame
            continue
        for i in range(0, len(v) - 1, 2):
            inside(v[i], v[i + 1], tag)
    elif tag == "text":
        size = float(e.get("font-size") or next(p.get("font-size") for p in root.iter() if e in list(p)))
        x, y = float(e.get("x")), float(e.get("y"))
        width = len(e.text) * 0.62 * size
        if (e.get("text-anchor") or "") == "middle" or any(e in list(p) and p.get("text-anchor") == "middle" for p in root.iter()):
            inside(x - width / 2, y - size, "text " + e.text); inside(x + width / 2, y, "text " + e.text)
        else:
            inside(x, y - size, "text " + e.text); inside(x + width, y, "text " + e.text)
    else:
        continue
    count += 1
assert count > 20, count

# One outline per object of the final world model, and none repeated as a hole.
dumps = txt.split("world model: ")
final = dumps[-1]
objects = re.findall(r"^\s+node \d+ (\S+)(?: held)? relation", final, re.M)
objects = [o for o in objects if o.startswith("object")]
outlines = [p for p in ids["model"].iter(ns + "path")]
assert len(outlines) == len(objects), (len(outlines), objects)
assert all(p.get("class") == "object" and p.get("d") for p in outlines)
names = sorted(p.find(ns + "title").text.split()[0].rstrip(",") for p in outlines)
assert names == sorted(objects), (names, objects)
corners = lambda d: frozenset(zip(numbers(d)[0::2], numbers(d)[1::2]))
object_rings = {corners(r) for p in outlines for r in re.findall(r"M[^Z]*Z", p.get("d"))}
floor_rings = [corners(r) for p in ids["floor-edge"].iter(ns + "path") for r in re.findall(r"M[^Z]*Z", p.get("d") or "")]
assert not object_rings & set(floor_rings), "a floor hole repeats an object's outline"

# The plan: pathgraph edges as well as vertices (skeleton planner); the route on top.
if planner == "skeleton" and "pathgraph" in ids:
    assert len(list(ids["pathgraph"].iter(ns + "polyline"))) > 0, "no pathgraph edges"
    assert len(list(ids["pathgraph"].iter(ns + "circle"))) > 0, "no pathgraph vertices"
order = [e.get("id") for e in root.iter() if e.get("id") in ("trail", "route", "skeleton", "model", "table")]
if "route" in order:
    assert order.index("route") > order.index("trail") > order.index("model") > order.index("table"), order
PY
done
