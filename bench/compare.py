#!/usr/bin/python3
# compare.py - `make bench-compare`: utak's distance transform and skeleton of free
# space (paper 4.2) against the peers issue 4 names, side by side in one run, on the
# same grids.
#
#   compare.py SKELBENCH DIR [MAP ...]
#
# SKELBENCH --compare DIR MAP... (bench/skelbench.c) writes the 1024 x 1024 rooms,
# rects and maze grids and each Moving AI MAP as DIR/NAME.pgm, with utak's distance
# transform as DIR/NAME.d2, and prints utak's times (best of 3, thread CPU time).
# This script then times, on the same files, in the same run and the same way (best
# of REPEAT, thread CPU time, one thread):
#   - OpenCV's exact distance transform: cv2.distanceTransform(DIST_L2,
#     DIST_MASK_PRECISE), against utak's skeleton_edt;
#   - scikit-image's skeletonize (Zhang's thinning in 2-D), and OpenCV's Zhang-Suen
#     thinning (cv2.ximgproc.thinning, when this OpenCV has the contrib module),
#     against utak's skeleton_compute, whose time includes its own distance
#     transform (skeletonize and thinning need none);
# and prints each peer's time over utak's: a ratio above 1 means utak is faster.
# Only ratios measured here, in this run, are printed: a comparison is never a
# figure copied from elsewhere.
#
# It also checks that the two distance transforms agree: OpenCV measures to the
# nearest zero pixel inside the image, utak counts the cells outside the grid as
# blocked, so OpenCV gets the image with a one-pixel blocked border, and the largest
# difference from sqrt(dist2) is printed (OpenCV returns float32, hence about 1e-5).
#
# Peers come from Debian's python3-opencv and python3-skimage (not pip), so this
# runs under Debian's /usr/bin/python3; the Makefile installs them when missing.
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

# Runs per figure, the least kept (the figure least disturbed by the shared machine);
# skelbench does the same number for utak's side.
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


def best_ms(fn, arg):
    """The least thread CPU time of REPEAT calls fn(arg), in ms, and the last result."""
    best, out = float("inf"), None
    for _ in range(REPEAT):
        t0 = time.thread_time()
        out = fn(arg)
        best = min(best, (time.thread_time() - t0) * 1e3)
    return best, out


def cv_edt(img):
    return cv2.distanceTransform(img, cv2.DIST_L2, cv2.DIST_MASK_PRECISE)


def sk_skeleton(img):
    return skeletonize(img > 0)


def cv_thinning(img):
    return cv2.ximgproc.thinning(img, thinningType=cv2.ximgproc.THINNING_ZHANGSUEN)


def main(argv):
    if len(argv) < 3:
        sys.stderr.write("usage: compare.py SKELBENCH DIR [MAP ...]\n")
        return 2
    skelbench, folder, maps = argv[1], argv[2], argv[3:]
    cv2.setNumThreads(1)
    has_thinning = hasattr(cv2, "ximgproc") and hasattr(cv2.ximgproc, "thinning")
    os.makedirs(folder, exist_ok=True)
    run = subprocess.run([skelbench, "--compare", folder] + maps, stdout=subprocess.PIPE,
                         universal_newlines=True, check=True)
    grids = [line.split()[1:] for line in run.stdout.splitlines() if line.startswith("grid ")]

    print("# one run, same grids: utak (bench/skelbench.c) and the peers, best of %d, "
          "thread CPU ms, one thread" % REPEAT)
    print("# OpenCV %s%s, scikit-image %s, numpy %s" % (
        cv2.__version__, "" if has_thinning else " (no ximgproc: thinning absent)",
        __import__("skimage").__version__, np.__version__))
    print("# ratio = peer ms / utak ms (above 1: utak faster); utak.skel includes its "
          "distance transform")
    print("%-14s %9s | %8s %8s %6s %9s | %9s %9s %6s %9s %6s | %8s %8s %8s" % (
        "grid", "size", "utak.edt", "cv2.edt", "ratio", "edt.diff", "utak.skel",
        "skimage", "ratio", "cv2.thin", "ratio", "utak.sk", "skimage", "cv2.thin"))
    for name, w, h, utak_edt, utak_skel, utak_cells in grids:
        utak_edt, utak_skel = float(utak_edt), float(utak_skel)
        img = read_pgm(os.path.join(folder, name + ".pgm"))
        edt_ms, _ = best_ms(cv_edt, img)
        # The check, untimed: the border makes OpenCV see the outside as blocked.
        padded = cv2.copyMakeBorder(img, 1, 1, 1, 1, cv2.BORDER_CONSTANT, value=0)
        theirs = cv_edt(padded)[1:-1, 1:-1].astype(np.float64)
        d2 = np.fromfile(os.path.join(folder, name + ".d2"), dtype=np.int32)
        ours = np.sqrt(d2.reshape(int(h), int(w)).astype(np.float64))
        diff = float(np.max(np.abs(theirs - ours)))
        sk_ms, sk = best_ms(sk_skeleton, img)
        line = "%-14s %9s | %8.2f %8.2f %6.2f %9.2e | %9.2f %9.2f %6.2f" % (
            name, w + "x" + h, utak_edt, edt_ms, edt_ms / utak_edt, diff, utak_skel, sk_ms,
            sk_ms / utak_skel)
        if has_thinning:
            th_ms, th = best_ms(cv_thinning, img)
            line += " %9.2f %6.2f" % (th_ms, th_ms / utak_skel)
            th_cells = "%8d" % int(np.count_nonzero(th))
        else:
            line += " %9s %6s" % ("absent", "-")
            th_cells = "%8s" % "-"
        line += " | %8d %8d %s" % (int(utak_cells), int(np.count_nonzero(sk)), th_cells)
        print(line)
        sys.stdout.flush()
    print("# edt.diff: largest |OpenCV - sqrt(utak dist2)| over the grid (OpenCV with a "
          "blocked border)")
    print("# utak.sk, skimage, cv2.thin: skeleton cells (utak's pruned, 4-connected; the "
          "thinnings' 8-connected)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
