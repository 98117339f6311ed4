"""The 3D-mouse benchmark's scoring: which reported gesture is which true one, whether the element
held the object through a gesture, and how much room the rules had. Pure functions of the run's
data (frames.csv, truth.csv): report.py renders them.
"""
import collections
import csv
import math

import numpy as np

TOLERANCE = 0.4     # s: a reported gesture matches a true one of its kind this close
TRACKING = {"ok", "reached-border"}
HELD_SHARE = 0.9    # a gesture was tracked when the object was reported on this share of the
HELD_AREA = 2.0     # frames around it, with an area within this factor of its usual share of
AROUND = 0.5        # the true area; around = this long before and after the gesture; and that
HELD_WHOLE = 0.5    # share at least this much (a piece of the object is not the object)
# The rise the margins are measured with, as docs/tracker.md states the detector's rule: the
# depth above a line through the depth of the last 0.7 s (the newest 0.1 s left out), against
# max(7 %, 5 × the scatter about that line).
TREND, GUARD, LEAST, NOISE_FACTOR = 0.7, 0.1, math.log1p(0.07), 5.0


def load_frames(path):
    """Rows of frames.csv grouped by (source, name), numbers parsed (None where empty)."""
    out = collections.defaultdict(list)
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            for k, v in r.items():
                if k in ("source", "name", "status", "gesture"):
                    continue
                r[k] = float(v) if v not in ("", None) else None
            out[(r["source"], r["name"])].append(r)
    return out


def load_truth(path):
    """True events by sequence name: dicts with kind, time, depth, duration, hold, gesture and
    the gesture's start and end (s)."""
    out = collections.defaultdict(list)
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            for k in ("time", "depth", "duration", "hold", "start", "end"):
                r[k] = float(r[k])
            r["gesture"] = int(r["gesture"])
            out[r["name"]].append(r)
    return out


def reported(rows):
    """The gestures the element reported: (kind, time s)."""
    return [(r["gesture"], r["time"]) for r in rows if r["gesture"]]


def match(truths, events):
    """Pairs each true event with the nearest unused report of its kind within TOLERANCE, in
    time order. Returns (latencies: one per true event, None when missed; unmatched reports)."""
    used, latencies = set(), []
    for t in truths:
        best = None
        for i, (kind, when) in enumerate(events):
            if i in used or kind != t["kind"] or abs(when - t["time"]) > TOLERANCE:
                continue
            if best is None or abs(when - t["time"]) < abs(events[best][1] - t["time"]):
                best = i
        if best is not None:
            used.add(best)
        latencies.append(None if best is None else events[best][1] - t["time"])
    return latencies, [e for i, e in enumerate(events) if i not in used]


def tracked(rows, start, end):
    """Whether the element held the object from AROUND s before `start` to AROUND s after `end`:
    reported on HELD_SHARE of those frames, its area within HELD_AREA of its median ratio to the
    true area, that ratio at least HELD_WHOLE (a piece of the object, or one that changes from
    frame to frame, is not the object)."""
    sel = [r for r in rows if start - AROUND <= r["time"] <= end + AROUND]
    held = [r for r in sel if r["status"] in TRACKING and r["area"]]
    if not sel or len(held) < HELD_SHARE * len(sel):
        return False
    ratio = [r["area"] / r["true_area"] for r in held]
    m = float(np.median(ratio))
    return m >= HELD_WHOLE and all(m / HELD_AREA <= x <= m * HELD_AREA for x in ratio)


def score_sequence(rows, truths):
    """Every true event with its latency (None: missed), whether it was tracked and the peak of
    its gesture's rise over the trend ÷ the threshold; the reports that match none;
    and the largest rise ÷ threshold away from every gesture (None: none measured)."""
    events = reported(rows)
    latencies, false = match(truths, events)
    excess = trend_excess(rows)
    scored = []
    for t, lat in zip(truths, latencies):
        peak = [x for s, x in excess if t["start"] <= s <= t["end"]]
        scored.append(dict(t, latency=lat, tracked=tracked(rows, t["start"], t["end"]),
                           excess=max(peak) if peak else None))
    quiet = [x for s, x in excess
             if not any(t["start"] - AROUND <= s <= t["end"] + AROUND for t in truths)]
    return scored, false, max(quiet) if quiet else None


def trend_excess(rows):
    """(time, rise over the trend ÷ the threshold) for every reported frame with a trend: the
    margins' measure, independent of the element's own state."""
    pts = [(r["time"], math.log(r["area"]) / 2) for r in rows
           if r["status"] in TRACKING and r["area"]]
    out = []
    for i, (t, v) in enumerate(pts):
        window = [(s, w) for s, w in pts[max(0, i - 60):i] if t - TREND - GUARD <= s <= t - GUARD]
        if len(window) < 5 or window[-1][0] - window[0][0] < 0.4:
            continue
        ts, vs = np.array(window).T
        slope, level = np.polyfit(ts - t, vs, 1)
        noise = 1.4826 * float(np.median(np.abs(vs - (level + slope * (ts - t)))))
        out.append((t, (v - level) / max(LEAST, NOISE_FACTOR * noise)))
    return out
