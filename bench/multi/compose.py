"""The several-objects benchmark's scenes, composed from a folder in DAVIS layout (read by
bench/davis/dataset.py): every scene is a list of frames with, per object, its true mask on every
frame.

- **Mosaic**: `cols` × `rows` sequences side by side, each at half size (427×240 of DAVIS's
  854×480), over the shortest length of them; each object's true mask is its sequence's, resized to
  half and placed in its tile. A 2×2 mosaic is a frame of DAVIS's size.
- **Crossing**: one sequence's object (the front), cut out of its frames by its true mask and
  scaled, pasted onto another sequence's frames (the back) at a position that sweeps across the back
  object (relative to its smoothed centroid) from beside it, over it, and out the other side; the
  back object's truth is what of it still shows (its mask less the pasted object), its whole mask is
  kept for its visible share.
"""
import collections
import os
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "davis"))
import dataset  # noqa: E402

# A scene: frames (BGR uint8), truths [per object: [bool mask per frame]], names [per object],
# full [per object: the whole masks before occlusion] (equal to truths but in crossings), and
# tiles [per object: (x, y, w, h) of its tile, or None].
Scene = collections.namedtuple("Scene", "name frames truths full names tiles")

HALF = 0.5


def half(frame, mask):
    """A frame and its mask at half size (the mask by area, kept where at least half covers)."""
    h, w = frame.shape[:2]
    size = (w // 2, h // 2)
    small = cv2.resize(frame, size, interpolation=cv2.INTER_AREA)
    m = cv2.resize(mask.astype(np.float32), size, interpolation=cv2.INTER_AREA) >= 0.5
    return small, m


def mosaic_groups(seqs, per, count=None):
    """Groups of `per` sequences, cycling through `seqs` in order so that each appears: as many
    groups as it takes for every sequence to appear once (or `count`)."""
    n = count or -(-len(seqs) // per)
    return [[seqs[(g * per + k) % len(seqs)] for k in range(per)] for g in range(n)]


def mosaic(root, seqs, cols, rows, limit=None):
    """The mosaic of `seqs` (cols × rows, row by row, each at half size) over the shortest of
    them (at most `limit` frames)."""
    assert len(seqs) == cols * rows
    lengths = [len(dataset.frame_names(root, s)) for s in seqs]
    n = min(lengths + ([limit] if limit else []))
    frames, truths, tiles = None, [], []
    for k, s in enumerate(seqs):
        fs, ms = dataset.load(root, s, n)
        small = [half(f, m) for f, m in zip(fs, ms)]
        th, tw = small[0][0].shape[:2]
        if frames is None:
            frames = [np.zeros((th * rows, tw * cols, 3), np.uint8) for _ in range(n)]
        x, y = (k % cols) * tw, (k // cols) * th
        truth = []
        for i, (f, m) in enumerate(small):
            frames[i][y:y + th, x:x + tw] = f
            full = np.zeros(frames[i].shape[:2], bool)
            full[y:y + th, x:x + tw] = m
            truth.append(full)
        truths.append(truth)
        tiles.append((x, y, tw, th))
    name = "+".join(seqs)
    return Scene(name, frames, truths, truths, list(seqs), tiles)


def smooth(values, radius=4):
    """A moving average (window 2·radius+1, shrunk at the ends)."""
    v = np.asarray(values, float)
    return np.array([v[max(0, i - radius):i + radius + 1].mean() for i in range(len(v))])


def centroid(mask):
    ys, xs = np.nonzero(mask)
    return (float(xs.mean()), float(ys.mean())) if len(xs) else None


def crossing_path(n, back_masks, front_w, back_w, width):
    """The front object's centre per frame: the back object's smoothed centroid, shifted sideways
    from D on one side (clear of it) on frame 0 to 1.3·D on the other on the last frame (clear of
    it some frames before the end, so that the back object has frames to be found again), D = half
    the front's width + half the back's median box width + 20 px. It comes from the side of the
    frame with more room on frame 0, three quarters of its width kept within the frame there."""
    cs = [centroid(m) for m in back_masks]
    last = next(c for c in cs if c is not None)
    filled = []
    for c in cs:
        last = c or last
        filled.append(last)
    cx, cy = smooth([c[0] for c in filled]), smooth([c[1] for c in filled])
    d = front_w / 2 + back_w / 2 + 20
    side = -1 if cx[0] > width / 2 else 1  # -1: from the left
    start = min(max(cx[0] + side * d, front_w / 4), width - front_w / 4)
    shift = np.linspace(start - cx[0], -side * 1.3 * d, n)
    return [(cx[i] + shift[i], cy[i]) for i in range(n)]


def paste(frame, cutout, cut_mask, centre):
    """The frame with `cutout` (its pixels where cut_mask) pasted with its box centre at `centre`
    (clipped to the frame); returns (frame, the pasted mask in the frame)."""
    out = frame.copy()
    pasted = np.zeros(frame.shape[:2], bool)
    h, w = cut_mask.shape
    x0, y0 = int(round(centre[0] - w / 2)), int(round(centre[1] - h / 2))
    fx0, fy0 = max(x0, 0), max(y0, 0)
    fx1, fy1 = min(x0 + w, frame.shape[1]), min(y0 + h, frame.shape[0])
    if fx1 <= fx0 or fy1 <= fy0:
        return out, pasted
    m = cut_mask[fy0 - y0:fy1 - y0, fx0 - x0:fx1 - x0]
    c = cutout[fy0 - y0:fy1 - y0, fx0 - x0:fx1 - x0]
    region = out[fy0:fy1, fx0:fx1]
    region[m] = c[m]
    pasted[fy0:fy1, fx0:fx1] = m
    return out, pasted


def cut(frame, mask, scale):
    """The object's pixels within its box, scaled: (pixels, mask); None when the mask is empty."""
    box = dataset.bbox(mask)
    if box is None:
        return None
    x, y, w, h = box
    size = (max(1, round(w * scale)), max(1, round(h * scale)))
    pix = cv2.resize(frame[y:y + h, x:x + w], size, interpolation=cv2.INTER_AREA)
    m = cv2.resize(mask[y:y + h, x:x + w].astype(np.float32), size,
                   interpolation=cv2.INTER_AREA) >= 0.5
    return pix, m


def median_size(masks):
    """The median width and height of the masks' boxes."""
    boxes = [b for b in (dataset.bbox(m) for m in masks) if b]
    return float(np.median([b[2] for b in boxes])), float(np.median([b[3] for b in boxes]))


def front_scale(front_masks, back_masks):
    """The front object's scale: its median box 1.2× as high as the back object's, or as wide,
    whichever is larger, within [0.3, 1.25] (so that it can hide most of the back object)."""
    (fw, fh), (bw, bh) = median_size(front_masks), median_size(back_masks)
    return float(np.clip(max(1.2 * bh / fh, bw / fw), 0.3, 1.25))


def crossing(root, front, back, limit=None):
    """`front`'s object crossing in front of `back`'s (see the module's comment), over the
    shorter of the two sequences (at most `limit` frames). Objects: [front, back]."""
    n = min(len(dataset.frame_names(root, front)), len(dataset.frame_names(root, back)),
            *([limit] if limit else []))
    ff, fm = dataset.load(root, front, n)
    bf, bm = dataset.load(root, back, n)
    scale = front_scale(fm, bm)
    cuts = [cut(f, m, scale) for f, m in zip(ff, fm)]
    width = float(np.median([c[1].shape[1] for c in cuts if c is not None]))
    back_w = median_size(bm)[0]
    for extra in range(0, 200, 20):  # wider apart until they do not touch on frame 0
        path = crossing_path(n, bm, width + extra, back_w, bf[0].shape[1])
        if cuts[0] is None or not (paste(bf[0], *cuts[0], path[0])[1] & bm[0]).any():
            break
    frames, front_truth, back_visible = [], [], []
    for i in range(n):
        if cuts[i] is None:
            frame, pasted = bf[i].copy(), np.zeros(bm[i].shape, bool)
        else:
            frame, pasted = paste(bf[i], cuts[i][0], cuts[i][1], path[i])
        frames.append(frame)
        front_truth.append(pasted)
        back_visible.append(bm[i] & ~pasted)
    name = f"{front} over {back}"
    return Scene(name, frames, [front_truth, back_visible], [front_truth, list(bm)],
                 [front, back], [None, None]), scale


def visible_share(scene, k, i):
    """The share of object k's whole mask that shows on frame i (NaN when it has none)."""
    whole = np.count_nonzero(scene.full[k][i])
    return np.count_nonzero(scene.truths[k][i]) / whole if whole else float("nan")
