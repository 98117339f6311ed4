"""The runs of the several-objects benchmark on one scene (compose.Scene), each started on frame 0
and run over frames 1 .. last, as a generator of (frame index, ms, {object: Prediction}) after a
first (0, init_ms, {}):

- **together**: one `projtrack.MultiTracker` following every object of the scene, each added on
  frame 0 from its first true mask or its box, then frame 0 tracked (as Tracker.init does); ms is
  the one call for all of them.
- **unlimited**: the same with no work budget (`max_work=0`).
- **alone**: one object followed by itself, `projtrack.Tracker` from the same start on the same
  frames (bench/davis/runners.py's run; a MultiTracker with one object follows it the same way:
  docs/tracker.md); one run per object.
- **CSRT**: OpenCV's CSRT from the object's box (bench/davis/runners.py's run), one per object.

A run whose tracker raises on a frame ends there: guarded() gives its frames left as misses
(status 'error') and keeps the message. A run that cannot start raises davis's
runners.NotMeasured (the module has no MultiTracker yet, or refused a start): the report then
reads "not measured", never a zero.
"""
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "davis"))
import dataset  # noqa: E402
import runners as davis_runners  # noqa: E402
from runners import NotMeasured, Prediction  # noqa: E402,F401  (davis's)

STARTS = ["mask", "box"]
# The `unlimited` runs' settings: together with no work budget (max_work 0), to tell what the
# shared budget takes from the objects from what following them together does.
UNLIMITED = {"max_work": 0}
MEASURED = {"ok", "reached-border"}  # the statuses that measured the object on the frame


def start_of(start, first_mask):
    """The keyword and value a start gives add(): the mask (uint8, 255 on it) or its box."""
    if start == "mask":
        return {"mask": np.where(first_mask, 255, 0).astype(np.uint8)}
    return {"box": dataset.bbox(first_mask)}


def multi_tracker(**settings):
    """A projtrack.MultiTracker, or NotMeasured when the module has none."""
    import projtrack
    if not hasattr(projtrack, "MultiTracker"):
        raise NotMeasured("the module has no MultiTracker")
    return projtrack.MultiTracker(**settings)


def result_mask(r, shape):
    """A result's silhouette as a bool mask of `shape` (empty when it has none)."""
    m = getattr(r, "mask", None)
    return m > 0 if m is not None else np.zeros(shape, bool)


def prediction(r, shape, ms):
    area = float(r.area) if r.centroid is not None and r.area else 0.0
    return Prediction(result_mask(r, shape), r.centroid, area, None, ms, r.status)


def add_all(tracker, frame, first_masks, start):
    """Adds every object (its index in first_masks) to `tracker` on `frame`: {index: id}, and
    the add's ms. A refused start is NotMeasured naming the object."""
    ids = {}
    t0 = time.perf_counter()
    for k, m in enumerate(first_masks):
        try:
            ids[k] = tracker.add(frame, **start_of(start, m))
        except ValueError as e:
            raise NotMeasured(f"object {k + 1}'s start from its {start} refused: {e}") from None
    return ids, 1e3 * (time.perf_counter() - t0)


def start_all(tracker, frame, first_masks, start):
    """add_all(), then frame 0 tracked: add() only takes the start, the object is tracked from the
    next frame given (the binding's add(): "give it `frame` again to start there"), as
    Tracker.init(frame, where) starts on that frame. Returns ({index: id}, ms of both)."""
    ids, add_ms = add_all(tracker, frame, first_masks, start)
    t0 = time.perf_counter()
    tracker.track(frame)
    return ids, add_ms + 1e3 * (time.perf_counter() - t0)


def together(scene, start, last, settings=None):
    """Every object of the scene in one MultiTracker (see the module's comment)."""
    t = multi_tracker(**(settings or {}))
    ids, init_ms = start_all(t, scene.frames[0], [tr[0] for tr in scene.truths], start)
    return _together_frames(t, ids, scene.frames, last, init_ms)


def _together_frames(t, ids, frames, last, init_ms):
    yield 0, init_ms, {}
    shape = frames[0].shape[:2]
    for i in range(1, last + 1):
        t0 = time.perf_counter()
        out = t.track(frames[i])
        ms = 1e3 * (time.perf_counter() - t0)
        preds = {}
        for k, oid in ids.items():
            r = out.get(oid)
            preds[k] = prediction(r, shape, ms) if r is not None else \
                Prediction(np.zeros(shape, bool), None, 0.0, None, ms, "missing")
        yield i, ms, preds


def guarded(gen, objects, shape, last, failure):
    """The frames of a started run (`gen` after its first yield) as they come; when the tracker
    raises, its message goes into `failure` and every frame left yields an empty prediction with
    status 'error' for each of `objects` (a miss, as a frame the tracker did not follow)."""
    i = 0
    try:
        for i, ms, preds in gen:
            yield i, ms, preds
        return
    except Exception as e:  # noqa: BLE001  (whatever the module raises ends the run there)
        failure.append(f"raised on frame {i + 1}: {type(e).__name__}: {str(e).strip()}")
    for f in range(i + 1, last + 1):
        yield f, math.nan, {o: Prediction(np.zeros(shape, bool), None, 0.0, None, math.nan,
                                          "error") for o in objects}


def alone(scene, k, start, last, model=None):
    """Object k by itself: projtrack.Tracker from its start, as the DAVIS benchmark runs it."""
    return _one(k, davis_runners.run_projtrack(start, scene.frames, scene.truths[k][0], last,
                                               model))


def csrt(scene, k, last):
    """Object k followed by OpenCV's CSRT from its box."""
    return _one(k, davis_runners.run_opencv("CSRT", scene.frames, scene.truths[k][0], last))


def _one(k, gen):
    _, init_ms = next(gen)
    yield 0, init_ms, {}
    for i, p in gen:
        yield i, p.ms, {k: p}
