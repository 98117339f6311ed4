"""The truth as silhouettes: a label's outlines rasterised into a mask, the mask moved as a variant
moves the frame (mirrored, cropped, halved), and a truth row and outlines measured back from it,
in the layout of bench/real/truth/<clip>.csv (area 0 and empty fields: not in view)."""
import csv
import gzip
import io
import math

import cv2
import numpy as np

HEADER = ["frame", "centroid_x", "centroid_y", "area", "x", "y", "width", "height", "inner_x",
          "inner_y", "luma_mean"]


def read_truth(path):
    """The rows of a truth CSV, numbers as floats; None for an empty field (not in view)."""
    with open(path, newline="") as f:
        return [{k: (float(v) if v != "" else None) for k, v in r.items()}
                for r in csv.DictReader(f)]


def in_view(row):
    return bool(row["area"])


def read_outlines(path):
    """{frame: [(kind, points)]} of an outlines CSV (gzipped)."""
    out = {}
    with gzip.open(path, "rt", newline="") as f:
        for r in csv.DictReader(f):
            pts = np.array([[int(v) for v in p.split(":")] for p in r["points"].split()],
                           np.int32)
            out.setdefault(int(r["frame"]), []).append((r["kind"], pts))
    return out


def rasterise(outlines, size):
    """The silhouette drawn by one frame's outlines on a frame of size (width, height): outer
    outlines filled, then holes cut."""
    w, h = size
    mask = np.zeros((h, w), np.uint8)
    for kind in ("outer", "hole"):
        for k, pts in outlines:
            if k == kind:
                cv2.fillPoly(mask, [pts], 1 if kind == "outer" else 0)
    return mask


def transform(mask, mirror=False, crop=None, scale=1.0):
    """The mask as the variant's frame shows it: mirrored, then cropped to crop = (x, y, w, h),
    then scaled (a pixel is in when at least half of it was)."""
    if mirror:
        mask = mask[:, ::-1]
    if crop:
        x, y, w, h = crop
        mask = mask[y:y + h, x:x + w]
    if scale != 1.0:
        h, w = mask.shape
        # Rounded half away from zero, as projtrack-real's std::lround: the frame's size.
        size = (math.floor(w * scale + 0.5), math.floor(h * scale + 0.5))
        mask = (cv2.resize(mask.astype(np.float32), size, interpolation=cv2.INTER_AREA) >= 0.5)
    return np.ascontiguousarray(mask, dtype=np.uint8)


def disc(size):
    """A disc-shaped structuring element (the labellers' morphology)."""
    return cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (size, size))


def fill_holes(mask):
    """Every pixel not 4-connected to the frame's border through zeros."""
    background = np.pad((mask == 0).astype(np.uint8), 1, constant_values=1)
    _, labels = cv2.connectedComponents(background, connectivity=4)
    return (labels != labels[0, 0])[1:-1, 1:-1].astype(np.uint8)


def farthest_inside(mask):
    """The silhouette's pixel farthest from its border (ties: the first in raster order), as the
    labels' inner point."""
    dist = cv2.distanceTransform(np.pad(mask, 1), cv2.DIST_L2, 5)[1:-1, 1:-1]
    y, x = np.unravel_index(int(np.argmax(dist)), dist.shape)
    return int(x), int(y)


def row_of(mask, frame, luma):
    """A truth row measured on a mask."""
    mo = cv2.moments(mask, True)
    if mo["m00"] == 0:
        return [frame, "", "", 0, "", "", "", "", "", "", luma]
    x, y, bw, bh = cv2.boundingRect(mask)
    ix, iy = farthest_inside(mask)
    return [frame, f"{mo['m10'] / mo['m00']:.2f}", f"{mo['m01'] / mo['m00']:.2f}",
            int(mo["m00"]), x, y, bw, bh, ix, iy, luma]


def outlines_of(mask):
    """[(kind, points)] of a mask, simplified to within 1 px (as the labels')."""
    contours, hierarchy = cv2.findContours(mask, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_SIMPLE)
    out = []
    for i, c in enumerate(contours):
        poly = cv2.approxPolyDP(c, 1.0, True).reshape(-1, 2)
        hole = hierarchy is not None and hierarchy[0][i][3] >= 0
        out.append(("hole" if hole else "outer", poly))
    return out


def write_truth(path, rows, outlines):
    """rows: truth rows (lists in HEADER's order); outlines: {frame: [(kind, points)]}."""
    with open(path + ".csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(HEADER)
        w.writerows(rows)
    with gzip.GzipFile(path + "_outlines.csv.gz", "wb", mtime=0) as raw:
        with io.TextIOWrapper(raw, newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["frame", "kind", "points"])
            for frame in sorted(outlines):
                for kind, pts in outlines[frame]:
                    w.writerow([frame, kind, " ".join(f"{x}:{y}" for x, y in pts)])


def fmt_row(r, frame):
    """A truth row read by read_truth, renumbered, back in HEADER's order."""
    def v(k, digits=0):
        x = r[k]
        if x is None:
            return ""
        return f"{x:.{digits}f}" if digits else int(x)
    return [frame, v("centroid_x", 2), v("centroid_y", 2), v("area") or 0, v("x"), v("y"),
            v("width"), v("height"), v("inner_x"), v("inner_y"), f"{r['luma_mean']:.2f}"]
