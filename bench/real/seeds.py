"""Where a user might start the tracker, from the first in-view frame's true silhouette (the
benchmark's starts): its deepest point (the point farthest from its border), the quarter points
(the point deepest inside the silhouette in each of its four quadrants about the centroid: the
middle of that part of the object) and its true box (`start-box`, and the box trackers' start)."""
import cv2
import numpy as np

from truth_geometry import farthest_inside


def quarter_points(mask, cx, cy):
    """The deepest point of each quadrant's own piece of the silhouette, about (cx, cy): up to
    four (x, y), top left, top right, bottom left, bottom right."""
    ys, xs = np.mgrid[0:mask.shape[0], 0:mask.shape[1]]
    out = []
    for below in (False, True):
        for right in (False, True):
            piece = mask.astype(bool) & ((xs >= cx) == right) & ((ys >= cy) == below)
            d = cv2.distanceTransform(np.pad(piece.astype(np.uint8), 1), cv2.DIST_L2, 5)
            if d.max() <= 0:
                continue
            y, x = np.unravel_index(int(np.argmax(d)), d.shape)
            out.append((int(x) - 1, int(y) - 1))
    return out


def seeds(mask):
    """[(kind, x, y, w, h)] for a silhouette: 'deepest', four 'quarter' points, 'box'."""
    mo = cv2.moments(mask, True)
    if mo["m00"] == 0:
        return []
    cx, cy = mo["m10"] / mo["m00"], mo["m01"] / mo["m00"]
    x, y = farthest_inside(mask)
    out = [("deepest", x, y, 0, 0)]
    out += [("quarter", qx, qy, 0, 0) for qx, qy in quarter_points(mask, cx, cy)]
    bx, by, bw, bh = cv2.boundingRect(mask)
    out.append(("box", bx, by, bw, bh))
    return out
