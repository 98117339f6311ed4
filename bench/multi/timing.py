"""The several-objects benchmark's cost run: on one 4×2 mosaic of eight sequences (each at half
size), a MultiTracker following the first 1, 2, 4 and 8 of its objects (with the default settings,
and one with no work budget, max_work=0) and as many OpenCV CSRT trackers, all on the same frames,
side by side: on every frame each MultiTracker's call is timed, then its CSRTs' calls (summed), one
count after the other, so that whatever else loads the machine loads both alike. With 8 objects,
the frame's work (the objects' TrackResult.work summed) against the frame's budget.

Writes cost.csv: one row per frame and count (objects; projtrack_ms, work, work_limits (the
objects' shares summed), statuses, and the same prefixed unlimited_ for the one with no budget;
csrt_ms).
"""
import csv
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "davis"))
import dataset  # noqa: E402
import runners as davis_runners  # noqa: E402

import runs  # noqa: E402

COUNTS = [1, 2, 4, 8]
LEAST_BUDGET_PIXELS = 1.5 * (1 << 20)  # include/projtrack/tracker_params.hpp's kLeastBudgetPixels
LEAST_FRAME_WORK = 1 << 18            # and kLeastFrameWork


def frame_limit(width, height, max_work):
    """A frame's work budget as the library computes it (frame_work_limit() in
    include/projtrack/tracker_params.hpp): max_work × its pixels, at least 1.5 MP's."""
    if not max_work or max_work <= 0:
        return float("inf")
    return max(LEAST_FRAME_WORK, min(max_work, 1e6) * max(width * height, LEAST_BUDGET_PIXELS))


def tracker_limit(frames, first_mask):
    """The frame's budget as projtrack.Tracker reports it (r.work_limit of one object alone on
    frame 1), to check frame_limit() against; None when it does not report one."""
    import projtrack
    t = projtrack.Tracker()
    t.init(frames[0], runs.start_of("mask", first_mask)["mask"])
    return getattr(t.track(frames[1]), "work_limit", None)


def timed(multi, frame, prefix):
    """One MultiTracker's call on `frame`, timed: the cost.csv fields (named with `prefix`)."""
    row = {prefix + k: "" for k in ("projtrack_ms", "work", "work_limits", "statuses")}
    if multi is None:
        return row
    t, ids, failure = multi
    if failure:  # it raised on an earlier frame: no more calls, its objects not followed
        row[prefix + "statuses"] = " ".join("error" for _ in ids)
        return row
    t0 = time.perf_counter()
    try:
        res = t.track(frame)
    except Exception as e:  # noqa: BLE001  (recorded in meta.json, the report says it)
        budget = "no budget" if prefix else "the default budget"
        failure.append(f"{len(ids)} objects, {budget}: {type(e).__name__}: {str(e).strip()}")
        row[prefix + "statuses"] = " ".join("error" for _ in ids)
        return row
    row[prefix + "projtrack_ms"] = f"{1e3 * (time.perf_counter() - t0):.3f}"
    rs = [res[oid] for oid in ids.values() if oid in res]
    if rs and all(hasattr(r, "work") for r in rs):
        row[prefix + "work"] = sum(int(r.work) for r in rs)
        row[prefix + "work_limits"] = sum(int(r.work_limit) for r in rs)
    row[prefix + "statuses"] = " ".join(r.status for r in rs)
    return row


def run(scene, out, log=print):
    """The cost run on `scene` (a mosaic of at least 8 objects) into out/cost.csv; returns a
    dict for meta.json (what was and was not measured)."""
    n = len(scene.frames)
    firsts = [tr[0] for tr in scene.truths]
    info = {"scene": scene.name, "frames": n, "counts": COUNTS,
            "size": f"{scene.frames[0].shape[1]}x{scene.frames[0].shape[0]}"}
    multis, note = {}, ""
    try:
        for c in COUNTS:
            for budget, settings in (("default", {}), ("unlimited", runs.UNLIMITED)):
                t = runs.multi_tracker(**settings)
                ids, _ = runs.start_all(t, scene.frames[0], firsts[:c], "mask")
                multis[(c, budget)] = (t, ids, [])
    except davis_runners.NotMeasured as e:
        multis, note = {}, str(e)
        log(f"  cost: projtrack not measured: {e}")
    info["projtrack_note"] = note
    import projtrack
    # every tracker here has the module's default settings: its max_work is a Tracker's
    info["max_work"] = projtrack.Tracker().settings.get("max_work")
    csrts = {}
    for c in COUNTS:
        trackers = []
        for m in firsts[:c]:
            tr = davis_runners.OPENCV["CSRT"]()
            tr.init(scene.frames[0], tuple(int(v) for v in dataset.bbox(m)))
            trackers.append(tr)
        csrts[c] = trackers
    try:
        info["tracker_work_limit"] = tracker_limit(scene.frames, firsts[0])
    except Exception as e:  # noqa: BLE001  (recorded, not fatal: the check reads "not measured")
        info["tracker_work_limit"] = None
        log(f"  cost: the Tracker's work_limit not read: {e}")
    rows = []
    for i in range(1, n):
        frame = scene.frames[i]
        for c in COUNTS:
            row = {"frame": i, "objects": c}
            for budget, prefix in (("default", ""), ("unlimited", "unlimited_")):
                row.update(timed(multis.get((c, budget)), frame, prefix))
            t0 = time.perf_counter()
            for tr in csrts[c]:
                tr.update(frame)
            row["csrt_ms"] = f"{1e3 * (time.perf_counter() - t0):.3f}"
            rows.append(row)
        if i % 10 == 0:
            log(f"  cost: frame {i} of {n - 1}")
    info["errors"] = [m[2][0] for m in multis.values() if m[2]]
    with open(os.path.join(out, "cost.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    h, w_ = scene.frames[0].shape[:2]
    info["frame_limit"] = frame_limit(w_, h, info.get("max_work") or 0) \
        if info.get("max_work") is not None else None
    return info
