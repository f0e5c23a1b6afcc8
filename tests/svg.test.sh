#!/bin/sh
# svg.test.sh - `--svg FILE` writes a well-formed SVG document (it must open in a
# browser): parsed as XML, its root is <svg> in the SVG namespace, and it holds the
# TABLE, the world model, the trail of the run and Utak.
set -e
tmp=${TMPDIR:-/tmp}/utak-svg.$$
mkdir -p "$tmp"; trap 'rm -rf "$tmp"' EXIT
for w in room tworooms; do
	"$UTAK" -q --svg "$tmp/$w.svg" "worlds/$w.w" "go ne-corner" >/dev/null
	python3 - "$tmp/$w.svg" <<'PY'
import sys
import xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
ns = "{http://www.w3.org/2000/svg}"
assert root.tag == ns + "svg", root.tag
ids = {e.get("id") for e in root.iter() if e.get("id")}
for want in ("table", "model", "trail", "utak"):
    assert want in ids, "no element with id " + want
assert len(list(root.iter(ns + "rect"))) > 10, "the TABLE is missing"
PY
done
