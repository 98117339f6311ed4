"""The DAVIS 2016 measures of one frame, and the share of frames a tracker kept.

- J: the intersection over union of the predicted and the true masks; an empty prediction of an
  empty truth counts as 1 (as DAVIS's db_eval_iou).
- F: DAVIS's boundary F-measure (db_eval_boundary): the one-pixel boundaries of both masks
  (seg2bmap), a boundary pixel matched when a pixel of the other boundary lies within
  ceil(0.008 × the image's diagonal) px of it; precision and recall of the matches give F.
- kept: the centroid within ¼·√(true area) of the true centroid and the area within [0.5, 2]×
  the true area; when the truth is empty, kept only if the prediction is empty too.
"""
import math

import cv2
import numpy as np

BOUND_TH = 0.008  # DAVIS's tolerance, a share of the image's diagonal


def region_j(pred, truth):
    """J of two bool masks of one size."""
    union = np.count_nonzero(pred | truth)
    if union == 0:
        return 1.0
    return np.count_nonzero(pred & truth) / union


def boundary(mask):
    """DAVIS's seg2bmap: the pixels of a bool mask that differ from their east, south or
    south-east neighbour (outside the image counts as background), one pixel wide."""
    m = mask.astype(bool)
    e = np.zeros_like(m)
    s = np.zeros_like(m)
    se = np.zeros_like(m)
    e[:, :-1] = m[:, 1:]
    s[:-1, :] = m[1:, :]
    se[:-1, :-1] = m[1:, 1:]
    b = (m ^ e) | (m ^ s) | (m ^ se)
    b[-1, :] = m[-1, :] ^ e[-1, :]
    b[:, -1] = m[:, -1] ^ s[:, -1]
    b[-1, -1] = False
    return b


def near(b, radius):
    """The pixels within `radius` px (Euclidean) of a pixel of the bool map b."""
    if not b.any():
        return np.zeros_like(b)
    dist = cv2.distanceTransform(np.where(b, 0, 255).astype(np.uint8), cv2.DIST_L2,
                                 cv2.DIST_MASK_PRECISE)
    return dist <= radius


def boundary_f(pred, truth, bound_th=BOUND_TH):
    """F of two bool masks of one size: (F, precision, recall)."""
    h, w = truth.shape
    radius = bound_th if bound_th >= 1 else math.ceil(bound_th * math.hypot(h, w))
    pb, tb = boundary(pred), boundary(truth)
    n_p, n_t = int(np.count_nonzero(pb)), int(np.count_nonzero(tb))
    if n_p == 0 and n_t == 0:
        return 1.0, 1.0, 1.0
    if n_p == 0:
        return 0.0, 1.0, 0.0
    if n_t == 0:
        return 0.0, 0.0, 1.0
    precision = np.count_nonzero(pb & near(tb, radius)) / n_p
    recall = np.count_nonzero(tb & near(pb, radius)) / n_t
    if precision + recall == 0:
        return 0.0, precision, recall
    return 2 * precision * recall / (precision + recall), precision, recall


def centroid_area(mask):
    """((x, y), area) of a bool mask in px; (None, 0) when it is empty."""
    ys, xs = np.nonzero(mask)
    if len(xs) == 0:
        return None, 0.0
    return (float(xs.mean()), float(ys.mean())), float(len(xs))


def kept(pred_centroid, pred_area, true_centroid, true_area):
    """Whether a frame is kept: the predicted centroid within ¼·√(true area) of the true one and
    the area within [0.5, 2]× the true area. A prediction is empty when its centroid is None or
    its area 0; an empty truth is kept only by an empty prediction."""
    pred_empty = pred_centroid is None or not pred_area
    if not true_area:
        return pred_empty
    if pred_empty:
        return False
    dx = pred_centroid[0] - true_centroid[0]
    dy = pred_centroid[1] - true_centroid[1]
    return (math.hypot(dx, dy) <= 0.25 * math.sqrt(true_area)
            and 0.5 * true_area <= pred_area <= 2.0 * true_area)


def box_centroid_area(box):
    """((x, y), area) of a box (x, y, w, h); (None, 0) for None or a box without area."""
    if box is None or box[2] <= 0 or box[3] <= 0:
        return None, 0.0
    x, y, w, h = box
    return (x + w / 2.0, y + h / 2.0), float(w * h)


def box_mask(box, shape):
    """A box (x, y, w, h) filled as a bool mask of `shape`, clipped to it; empty for None."""
    m = np.zeros(shape, bool)
    if box is None:
        return m
    x, y, w, h = (int(round(v)) for v in box)
    x0, y0 = max(x, 0), max(y, 0)
    x1, y1 = min(x + w, shape[1]), min(y + h, shape[0])
    if x1 > x0 and y1 > y0:
        m[y0:y1, x0:x1] = True
    return m


def scored_frames(n):
    """The frames DAVIS 2016 scores in a sequence of n frames: 1 .. n-2."""
    return range(1, n - 1)
