#!/usr/bin/python3
"""Other points a user might click: for each clip with a truth, the point deepest inside frame 0's
true silhouette in each of its four quadrants about the centroid (the benchmark's main seed is
the deepest point of all). Writes CLIP,X,Y rows to OUT for `projtrack-real --seeds`.

usage: bench/real/seeds.py TRUTH_DIR OUT CLIP...
"""
import csv
import gzip
import os
import sys

import cv2
import numpy as np


def first_silhouette(truth_dir, clip, size):
    mask = np.zeros(size[::-1], np.uint8)
    with gzip.open(os.path.join(truth_dir, clip + "_outlines.csv.gz"), "rt", newline="") as f:
        rows = [r for r in csv.DictReader(f) if int(r["frame"]) == 0]
    for kind in ("outer", "hole"):  # holes cut after every outer outline is drawn
        for r in rows:
            if r["kind"] != kind:
                continue
            pts = np.array([[int(v) for v in p.split(":")] for p in r["points"].split()],
                           np.int32)
            cv2.fillPoly(mask, [pts], 1 if kind == "outer" else 0)
    return mask


def main():
    truth_dir, out, clips = sys.argv[1], sys.argv[2], sys.argv[3:]
    with open(out, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["clip", "x", "y"])
        for clip in clips:
            if not os.path.exists(os.path.join(truth_dir, clip + "_outlines.csv.gz")):
                continue
            with open(os.path.join(truth_dir, clip + ".csv"), newline="") as t:
                first = next(csv.DictReader(t))
            # The outlines stay inside the frame the truth was labelled on.
            size = (int(first["x"]) + int(first["width"]) + 2,
                    int(first["y"]) + int(first["height"]) + 2)
            mask = first_silhouette(truth_dir, clip, size)
            cx, cy = float(first["centroid_x"]), float(first["centroid_y"])
            ys, xs = np.mgrid[0:mask.shape[0], 0:mask.shape[1]]
            for below in (False, True):
                for right in (False, True):
                    # Deepest in the quadrant's own piece: the middle of that part of the object.
                    piece = (mask.astype(bool) & ((xs >= cx) == right) & ((ys >= cy) == below))
                    d = cv2.distanceTransform(piece.astype(np.uint8), cv2.DIST_L2, 5)
                    if d.max() <= 0:
                        continue
                    y, x = np.unravel_index(np.argmax(d), d.shape)
                    w.writerow([clip, int(x), int(y)])


if __name__ == "__main__":
    main()
