"""A folder in DAVIS layout: its sequences, their frames and masks, and the published J per
sequence that davis-dev/README.md quotes.

    JPEGImages/480p/<sequence>/00000.jpg ...   the frames
    Annotations/480p/<sequence>/00000.png ...  the masks, 0 = background, non-zero = the object
"""
import os
import re

import cv2
import numpy as np

# Where davis-dev/README.md's table of published J comes from (quoted by the report).
PUBLISHED_SOURCE = "DAVIS 2016 evaluation files, davisvideochallenge/davis-matlab"


def default_dir(repo):
    """The development split beside the repository: <repo>/../shared/davis-dev."""
    return os.path.normpath(os.path.join(repo, "..", "shared", "davis-dev"))


def check_dir(root):
    """Exits with a clear message when root is not a folder in DAVIS layout."""
    for sub in ("JPEGImages/480p", "Annotations/480p"):
        if not os.path.isdir(os.path.join(root, sub)):
            raise SystemExit(f"davis: {root} is not a DAVIS folder (no {sub}/<sequence>/); "
                             "give one: ./run bench --davis DIR")


def sequences(root):
    """The sequences that have both frames and masks, in name order."""
    frames = set(os.listdir(os.path.join(root, "JPEGImages", "480p")))
    masks = set(os.listdir(os.path.join(root, "Annotations", "480p")))
    return sorted(frames & masks)


def frame_names(root, seq):
    """The frames' file stems (00000, 00001, ...) that have a mask, in order."""
    jpg = {os.path.splitext(n)[0] for n in os.listdir(os.path.join(root, "JPEGImages", "480p", seq))
           if n.endswith(".jpg")}
    png = {os.path.splitext(n)[0]
           for n in os.listdir(os.path.join(root, "Annotations", "480p", seq)) if n.endswith(".png")}
    return sorted(jpg & png)


def load(root, seq, limit=None):
    """(frames, masks) of a sequence: BGR uint8 frames and bool masks, the first `limit` of them."""
    names = frame_names(root, seq)[:limit]
    frames, masks = [], []
    for n in names:
        frame = cv2.imread(os.path.join(root, "JPEGImages", "480p", seq, n + ".jpg"),
                           cv2.IMREAD_COLOR)
        mask = cv2.imread(os.path.join(root, "Annotations", "480p", seq, n + ".png"),
                          cv2.IMREAD_GRAYSCALE)
        if frame is None or mask is None:
            raise SystemExit(f"davis: cannot read {seq}/{n}")
        frames.append(frame)
        masks.append(mask > 0)
    return frames, masks


def published(root):
    """The published J per sequence from <root>/README.md's table: ({method: {sequence: J}},
    [methods in the table's order]); empty when the README has no such table."""
    path = os.path.join(root, "README.md")
    if not os.path.exists(path):
        return {}, []
    methods, table = [], {}
    for line in open(path, encoding="utf-8"):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("|") or len(cells) < 2:
            continue
        if cells[0] == "sequence" and not methods and all(re.fullmatch(r"[A-Za-z0-9-]+", c)
                                                            for c in cells[1:]) \
                and cells[1] != "frames":
            methods = cells[1:]
            table = {m: {} for m in methods}
            continue
        if methods and len(cells) == len(methods) + 1 and not cells[0].startswith("**") \
                and not set(cells[0]) <= set("-"):
            try:
                values = [float(c) for c in cells[1:]]
            except ValueError:
                continue
            for m, v in zip(methods, values):
                table[m][cells[0]] = v
    return table, methods


def bbox(mask):
    """The tight box (x, y, w, h) of a bool mask, or None when it is empty."""
    ys, xs = np.nonzero(mask)
    if len(xs) == 0:
        return None
    x0, y0 = int(xs.min()), int(ys.min())
    return x0, y0, int(xs.max()) - x0 + 1, int(ys.max()) - y0 + 1


def deepest_point(mask):
    """(x, y) of the maximum of the mask's distance transform: the point deepest inside it."""
    dist = cv2.distanceTransform(mask.astype(np.uint8), cv2.DIST_L2, cv2.DIST_MASK_PRECISE)
    y, x = np.unravel_index(int(np.argmax(dist)), dist.shape)
    return int(x), int(y)
