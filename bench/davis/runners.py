"""The trackers the DAVIS benchmark runs, each started on frame 0 and run over frames 1 .. last:
projtrack (the Python module) from the first mask, its box or a click at its deepest point; the
first mask held still; OpenCV's CSRT, KCF, MOSSE and MedianFlow from the box.

A runner is a generator of (frame index, Prediction) for frames 1 .. last; it raises NotMeasured
before its first frame when the tracker cannot be started that way (the mask start on a module
that does not take a mask yet). ms is time.perf_counter around the tracker's call on that frame
only (NaN when nothing is called: the held mask).
"""
import collections
import math
import time

import cv2
import numpy as np

import dataset
import measures

# mask: bool (H, W); centroid (x, y) or None; area px²; box (x, y, w, h) or None (the box
# trackers'); status: the tracker's word for the frame.
Prediction = collections.namedtuple("Prediction", "mask centroid area box ms status")

PROJTRACK_STARTS = ["mask", "box", "click"]  # in the report's order
OPENCV = {  # name: constructor (OpenCV 4.6 with contrib, as Debian ships it)
    "CSRT": lambda: cv2.TrackerCSRT_create(),
    "KCF": lambda: cv2.TrackerKCF_create(),
    "MOSSE": lambda: cv2.legacy.TrackerMOSSE_create(),
    "MedianFlow": lambda: cv2.legacy.TrackerMedianFlow_create(),
}


class NotMeasured(Exception):
    """The tracker cannot be started this way: the run is not measured (why: the message)."""


def plan(model=None):
    """Every (tracker, start) the benchmark runs, in the report's order."""
    runs = [("projtrack", s) for s in PROJTRACK_STARTS] + [("hold", "mask")]
    return runs + [(name, "box") for name in OPENCV]


def runner(tracker, start, frames, first_mask, last, model=None):
    """The generator of one run over frames 1 .. last (see the module's comment)."""
    if tracker == "projtrack":
        return run_projtrack(start, frames, first_mask, last, model)
    if tracker == "hold":
        return run_hold(frames, first_mask, last)
    return run_opencv(tracker, frames, first_mask, last)


def make_projtrack(model=None):
    """A projtrack.Tracker with the model asked for (the module's default when None)."""
    import projtrack
    return projtrack.Tracker(model=model) if model else projtrack.Tracker()


def run_projtrack(start, frames, first_mask, last, model=None):
    t = make_projtrack(model)
    if start == "mask":
        where = np.where(first_mask, 255, 0).astype(np.uint8)
    elif start == "box":
        where = dataset.bbox(first_mask)
    else:
        where = dataset.deepest_point(first_mask)
    try:
        t0 = time.perf_counter()
        t.init(frames[0], where)
        init_ms = 1e3 * (time.perf_counter() - t0)
    except (TypeError, ValueError) as e:
        if start != "mask":
            raise
        raise NotMeasured(f"the module does not take a mask start: {e}") from None
    return _projtrack_frames(t, frames, last, init_ms)


def _projtrack_frames(t, frames, last, init_ms):
    yield 0, init_ms
    for i in range(1, last + 1):
        t0 = time.perf_counter()
        r = t.track(frames[i])
        ms = 1e3 * (time.perf_counter() - t0)
        mask = r.mask > 0 if r.mask is not None else np.zeros(frames[i].shape[:2], bool)
        area = float(r.area) if r.centroid is not None and r.area else 0.0
        yield i, Prediction(mask, r.centroid, area, None, ms, r.status)


def run_hold(frames, first_mask, last):
    centroid, area = measures.centroid_area(first_mask)
    yield 0, math.nan
    for i in range(1, last + 1):
        yield i, Prediction(first_mask, centroid, area, None, math.nan, "held")


def run_opencv(name, frames, first_mask, last):
    tracker = OPENCV[name]()
    box = dataset.bbox(first_mask)
    t0 = time.perf_counter()
    tracker.init(frames[0], tuple(int(v) for v in box))
    init_ms = 1e3 * (time.perf_counter() - t0)
    return _opencv_frames(tracker, frames, last, init_ms)


def _opencv_frames(tracker, frames, last, init_ms):
    yield 0, init_ms
    shape = frames[0].shape[:2]
    for i in range(1, last + 1):
        t0 = time.perf_counter()
        ok, box = tracker.update(frames[i])
        ms = 1e3 * (time.perf_counter() - t0)
        box = tuple(float(v) for v in box) if ok else None
        centroid, area = measures.box_centroid_area(box)
        yield i, Prediction(measures.box_mask(box, shape), centroid, area, box, ms,
                            "ok" if ok else "lost")
