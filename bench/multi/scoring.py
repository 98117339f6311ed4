"""The several-objects benchmark's measures of one object on one frame, beside DAVIS's J and kept
(bench/davis/measures.py):

- **identity kept**: the object's reported silhouette (a box tracker's box, filled) overlaps its
  own object's true mask, and more of it than of any other object's: its id is on its own object.
- **on the others**: the share of its reported silhouette that lies on the other objects' true
  (visible) masks — in a crossing, how much of the front object the hidden one was given.
- **visible**: the share of the object's whole mask that shows (1 but where another covers it).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "davis"))
import dataset  # noqa: E402
import measures  # noqa: E402

import compose  # noqa: E402


def identity(pred, truths, k):
    """Whether the silhouette `pred` lies on object k more than on any other (truths: the
    objects' true masks on the frame)."""
    overlaps = [np.count_nonzero(pred & t) for t in truths]
    own = overlaps[k]
    return own > 0 and all(own > o for j, o in enumerate(overlaps) if j != k)


def on_others(pred, truths, k):
    """The share of `pred` on the other objects' true masks; NaN when pred is empty."""
    n = np.count_nonzero(pred)
    if not n:
        return float("nan")
    others = np.zeros_like(pred)
    for j, t in enumerate(truths):
        if j != k:
            others |= t
    return np.count_nonzero(pred & others) / n


def frame_row(scene, k, i, p, box_tracker=False):
    """The measures of object k's prediction p on frame i of the scene, as a row's fields (a box
    tracker's kept compares its box with the true box)."""
    truths = [tr[i] for tr in scene.truths]
    truth = truths[k]
    tc, ta = measures.centroid_area(truth)
    if box_tracker:
        # a box tracker's kept: its box against the true box (as bench/davis does)
        tc, ta = measures.box_centroid_area(dataset.bbox(truth))
    share = on_others(p.mask, truths, k)
    return {"j": f"{measures.region_j(p.mask, truth):.5f}",
            "identity": int(identity(p.mask, truths, k)),
            "kept": int(measures.kept(p.centroid, p.area, tc, ta)),
            "on_others": "" if np.isnan(share) else f"{share:.4f}",
            "visible": f"{compose.visible_share(scene, k, i):.4f}",
            "status": p.status,
            "pred_area": f"{p.area:.0f}", "true_area": int(ta)}


HIDDEN = 0.5  # an object shows less than this share of itself: hidden; more again: come out


def hidden_span(visible):
    """(first, out) of an object's visible shares per frame: the first frame on which less than
    half of it shows, and the frame after the last such frame (from there on more than half shows:
    it has come out); None when it is never hidden."""
    hidden = [i for i, v in enumerate(visible) if v < HIDDEN]
    return (hidden[0], hidden[-1] + 1) if hidden else None
