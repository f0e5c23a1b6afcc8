#!/usr/bin/python3
# compare.py - `make bench-compare`: utak's distance transform, skeleton of free space
# (paper 4.2) and grid A* (paper 4.1) against the peers issues 4 and 16 name, side by
# side in one run, on the same grids.
#
#   compare.py SKELBENCH TCODPATH DIR [--side N] [MAP ...]
#
# With --side N only the grids N cells a side are made and timed (a reduced run, a few
# minutes at 1024 instead of about 40 for both sizes; `make bench-compare SIDE=1024`).
#
# SKELBENCH --compare DIR MAP... (bench/skelbench.c) writes the rooms, rects (random
# rectangles) and maze grids and each Moving AI MAP (scaled and cut to the size) at
# 1024 and 4096 cells a side as DIR/NAME-SIDE.pgm, with utak's distance transform as
# DIR/NAME-SIDE.d2, and prints utak's figures: one read pass over the grid (the
# physical limit of any job on it), skeleton_edt, skeleton_compute (its distance
# transform included), pathgraph_build, and gridpath_find corner to corner by plain
# A* and by the jump-point search; each the median of its runs with the least and
# the most. This script then times, on the same files, in the same run and the same
# way (median of REPEAT runs, thread CPU time, one thread):
#   - OpenCV's exact distance transform: cv2.distanceTransform(DIST_L2,
#     DIST_MASK_PRECISE), against utak's skeleton_edt;
#   - scikit-image's skeletonize (Zhang's thinning in 2-D), and OpenCV's Zhang-Suen
#     thinning (cv2.ximgproc.thinning, when this OpenCV has the contrib module),
#     against utak's skeleton_compute, whose time includes its own distance
#     transform (skeletonize and thinning need none);
#   - libtcod's A* (Debian's libtcod-dev, through TCODPATH, bench/peer/tcodpath.c,
#     with this project's no-corner-cutting rule) on the same ends, against utak's
#     A* and its jump-point search; the lengths must agree;
# and prints each peer's time over utak's: a ratio above 1 means utak is faster.
# Only ratios measured here, in this run, are printed: a comparison is never a
# figure copied from elsewhere.
#
# It also checks that the two distance transforms agree: OpenCV measures to the
# nearest zero pixel inside the image, utak counts the cells outside the grid as
# blocked, so OpenCV gets the image with a one-pixel blocked border, and the largest
# difference from sqrt(dist2) is printed (OpenCV returns float32, hence about 1e-5).
#
# Peers come from Debian's python3-opencv, python3-skimage and libtcod-dev (not pip),
# so this runs under Debian's /usr/bin/python3; the Makefile installs them when
# missing.
import os

# Before numpy and OpenCV load: one thread, for them and for anything they call.
os.environ["OMP_NUM_THREADS"] = "1"
os.environ["OPENBLAS_NUM_THREADS"] = "1"

import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import cv2  # noqa: E402
import numpy as np  # noqa: E402
from skimage.morphology import skeletonize  # noqa: E402

# Runs per peer figure: the median is kept, with the least and the most (skelbench
# runs utak's side 5 times).
REPEAT = 3


def read_pgm(path):
    """A binary PGM (P5, maxval 255) as a 2-D uint8 array."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    if fields[0] != b"P5" or int(fields[3]) != 255:
        raise ValueError(path + ": not a binary PGM with maxval 255")
    w, h = int(fields[1]), int(fields[2])
    pixels = np.frombuffer(data, dtype=np.uint8, count=w * h, offset=pos + 1)
    return pixels.reshape(h, w)


def median_ms(fn, arg):
    """(median, least, most) thread CPU time of REPEAT calls fn(arg), in ms, and the
    last result."""
    times, out = [], None
    for _ in range(REPEAT):
        t0 = time.thread_time()
        out = fn(arg)
        times.append((time.thread_time() - t0) * 1e3)
    times.sort()
    n = len(times)
    med = times[n // 2] if n % 2 else (times[n // 2 - 1] + times[n // 2]) / 2
    return (med, times[0], times[-1]), out


def parse_grid(line):
    """One "grid ..." line of skelbench --compare as a dict."""
    f = line.split()
    g = {"name": f[1], "w": int(f[2]), "h": int(f[3]),
         "ends": [int(v) for v in f[5:9]], "len": (float(f[10]), float(f[11])),
         "exp": (int(f[13]), int(f[14])), "skcells": int(f[16])}
    k = 17
    while k < len(f):
        g[f[k]] = (float(f[k + 1]), float(f[k + 2]), float(f[k + 3]))
        k += 4
    return g


def fig(t):
    """A figure: median and spread."""
    return "%.2f (%.2f-%.2f)" % t


def cv_edt(img):
    return cv2.distanceTransform(img, cv2.DIST_L2, cv2.DIST_MASK_PRECISE)


def sk_skeleton(img):
    return skeletonize(img > 0)


def cv_thinning(img):
    return cv2.ximgproc.thinning(img, thinningType=cv2.ximgproc.THINNING_ZHANGSUEN)


def main(argv):
    if len(argv) < 4:
        sys.stderr.write("usage: compare.py SKELBENCH TCODPATH DIR [--side N] [MAP ...]\n")
        return 2
    skelbench, tcodpath, folder, maps = argv[1], argv[2], argv[3], argv[4:]
    side = []
    if maps[:1] == ["--side"] and len(maps) >= 2:
        side, maps = maps[:2], maps[2:]
    cv2.setNumThreads(1)
    has_thinning = hasattr(cv2, "ximgproc") and hasattr(cv2.ximgproc, "thinning")
    os.makedirs(folder, exist_ok=True)
    run = subprocess.run([skelbench, "--compare", folder] + side + maps, stdout=subprocess.PIPE,
                         universal_newlines=True, check=True)
    grids = [parse_grid(line) for line in run.stdout.splitlines() if line.startswith("grid ")]

    print("# one run, same grids: utak (bench/skelbench.c, 5 runs) and the peers (%d runs);"
          " each figure the median (least-most), thread CPU ms, one thread" % REPEAT)
    print("# OpenCV %s%s, scikit-image %s, numpy %s, libtcod (Debian libtcod-dev) via "
          "bench/peer/tcodpath.c" % (
              cv2.__version__, "" if has_thinning else " (no ximgproc: thinning absent)",
              __import__("skimage").__version__, np.__version__))
    print("# read = one pass reading the grid's bytes: the physical limit beside each job; "
          "x = job / read")
    rows = []
    for g in grids:
        name, w, h = g["name"], g["w"], g["h"]
        base = os.path.join(folder, "%s-%d" % (name, w))
        img = read_pgm(base + ".pgm")
        edt, _ = median_ms(cv_edt, img)
        # The check, untimed: the border makes OpenCV see the outside as blocked.
        padded = cv2.copyMakeBorder(img, 1, 1, 1, 1, cv2.BORDER_CONSTANT, value=0)
        theirs = cv_edt(padded)[1:-1, 1:-1].astype(np.float64)
        d2 = np.fromfile(base + ".d2", dtype=np.int32)
        ours = np.sqrt(d2.reshape(h, w).astype(np.float64))
        diff = float(np.max(np.abs(theirs - ours)))
        sk, _ = median_ms(sk_skeleton, img)
        th = median_ms(cv_thinning, img)[0] if has_thinning else None
        sx, sy, gx, gy = g["ends"]
        out = subprocess.run([tcodpath, base + ".pgm", str(sx), str(sy), str(gx), str(gy),
                              str(REPEAT)], stdout=subprocess.PIPE, universal_newlines=True,
                             check=True).stdout.split()
        tcod, tcod_len = (float(out[1]), float(out[2]), float(out[3])), float(out[4])
        same = abs(tcod_len - g["len"][0]) <= 1e-3 + 1e-5 * g["len"][0]
        rows.append((g, edt, diff, sk, th, tcod, tcod_len, same))
        sys.stderr.write("compare.py: %s %d done\n" % (name, w))

    print()
    print("## times, ms: median (least-most)")
    print("%-14s %5s | %-19s | %-20s %-20s | %-20s %-22s %-22s | %-22s %-20s %-22s | %-18s" % (
        "grid", "side", "read (limit)", "utak.edt", "cv2.edt", "utak.skel", "skimage",
        "cv2.thin", "utak.A*", "utak.jps", "libtcod.A*", "utak.pg"))
    for g, edt, diff, sk, th, tcod, tcod_len, same in rows:
        print("%-14s %5d | %-19s | %-20s %-20s | %-20s %-22s %-22s | %-22s %-20s %-22s | %-18s" % (
            g["name"], g["w"], fig(g["read"]), fig(g["edt"]), fig(edt), fig(g["skel"]),
            fig(sk), fig(th) if th else "absent", fig(g["astar"]), fig(g["jps"]),
            fig(tcod), fig(g["pg"])))

    print()
    print("## ratios peer / utak (medians; goal >= 5, A* with jump points >= 10), and "
          "utak's multiple of the read pass")
    print("%-14s %5s | %7s %6s | %7s %7s %6s | %7s %7s %6s %6s | %6s %6s | %7s %8s %s" % (
        "grid", "side", "edt", "x read", "skel/sk", "skel/th", "x read", "A*", "jps",
        "x read", "pg ms", "pg<=2", "edt.df", "length", "expanded", "lengths"))
    for g, edt, diff, sk, th, tcod, tcod_len, same in rows:
        rd = g["read"][0]
        print("%-14s %5d | %7.2f %6.0f | %7.2f %7s %6.0f | %7.2f %7.2f %6.0f %6.0f | %6.2f %6s"
              " | %.1e %8.1f %d/%d %s" % (
                  g["name"], g["w"], edt[0] / g["edt"][0], g["edt"][0] / rd,
                  sk[0] / g["skel"][0], "%.2f" % (th[0] / g["skel"][0]) if th else "-",
                  g["skel"][0] / rd, tcod[0] / g["astar"][0], tcod[0] / g["jps"][0],
                  g["astar"][0] / rd, g["jps"][0] / rd, g["pg"][0],
                  "yes" if g["pg"][0] <= 2 else "no", diff, g["len"][0], g["exp"][0],
                  g["exp"][1], "agree" if same and g["len"][0] == g["len"][1]
                  else "DIFFER (libtcod %.4f)" % tcod_len))
    print("# edt.df: largest |OpenCV - sqrt(utak dist2)| (OpenCV with a blocked border); "
          "expanded: cells by A*/jump points by the jump search")
    print("# A*, jps: libtcod ms / utak's A* ms and / its jump-point search ms; skel/sk and "
          "skel/th: scikit-image and OpenCV thinning over utak's skeleton")
    if not all(r[7] for r in rows):
        sys.stderr.write("compare.py: a libtcod path length differs from utak's\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
