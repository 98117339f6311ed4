"""A several-objects run's data (run.py's frames.csv, runs.csv, cost.csv, meta.json) as the report
reads it, and the numbers its targets rest on. A run that was not measured gives NaN (the report
writes it "not measured", and a target resting on it is not met), never a zero."""
import collections
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "davis"))
from results import mean, median  # noqa: E402,F401  (davis's: one mean and median)

import scoring  # noqa: E402

NAN = math.nan
MEASURED = {"ok", "reached-border"}
REFOUND_WITHIN = 10  # frames after coming out


def _read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class Run:
    def __init__(self, data_dir):
        self.dir = data_dir
        with open(os.path.join(data_dir, "meta.json")) as f:
            self.meta = json.load(f)
        self.scenes = {s["name"]: s for s in self.meta["scenes"]}
        self.runs = {(r["scene"], r["run"], r["start"], int(r["object"])): r
                     for r in _read(os.path.join(data_dir, "runs.csv"))}
        self.rows = collections.defaultdict(list)  # (scene, run, start, object): rows by frame
        for r in _read(os.path.join(data_dir, "frames.csv")):
            self.rows[(r["scene"], r["run"], r["start"], int(r["object"]))].append(r)
        path = os.path.join(data_dir, "cost.csv")
        self.cost = _read(path) if os.path.exists(path) else []

    def of_kind(self, kind):
        return [s for s in self.meta["scenes"] if s["kind"] == kind]

    def measured(self, scene, run, start, k):
        r = self.runs.get((scene, run, start, k))
        return bool(r and r["measured"] == "1" and self.rows.get((scene, run, start, k)))

    def note(self, run, start):
        """Why a run was not measured (the first one's word), or ''."""
        for (_, r, s, _), row in self.runs.items():
            if (r, s) == (run, start) and row["measured"] != "1":
                return row["note"]
        return ""

    def values(self, scene, run, start, k, field):
        """{frame: value} of one object's run; {} when not measured."""
        if not self.measured(scene, run, start, k):
            return {}
        out = {}
        for r in self.rows[(scene, run, start, k)]:
            v = r[field]
            out[int(r["frame"])] = v if field == "status" else (float(v) if v != "" else NAN)
        return out

    def mean_of(self, scene, run, start, k, field):
        v = self.values(scene, run, start, k, field)
        return mean(v.values()) if v else NAN


def pooled(values):
    """The mean of values, NaN when there are none or any is NaN (a run not measured)."""
    values = list(values)
    if not values or any(math.isnan(v) for v in values):
        return NAN
    return mean(values)


# ---- crossings ------------------------------------------------------------------------------------

def crossing_numbers(run, scene, start, name="together"):
    """What a crossing's together run (`name`: or the unlimited one; from `start`) did with the
    back object (object 1) — NaN or None where not measured:
      hidden       frames (scored) on which less than half of it shows
      occluded     the share of them it was reported 'occluded'
      on_front     mean share of its silhouette on the front object over the scored frames on
                   which the two overlap and it is reported measured (its pixels, it claims)
      on_front_max the most of those
      out          the frame from which more than half of it shows again (scoring.hidden_span)
      refound      the first frame from `out` on which it is reported measured and kept (DAVIS's
                   kept against what of it shows); delay = refound - out
    """
    s = run.scenes[scene]
    vis = s["visible"]
    n = s["frames"]
    scored = range(1, n - 1)
    status = run.values(scene, name, start, 1, "status")
    kept = run.values(scene, name, start, 1, "kept")
    share = run.values(scene, name, start, 1, "on_others")
    out = {"hidden": [i for i in scored if vis[i] < scoring.HIDDEN], "occluded": NAN,
           "on_front": NAN, "on_front_max": NAN, "out": None, "refound": None, "delay": NAN,
           "measured": bool(status)}
    span = scoring.hidden_span(vis)
    out["out"] = span[1] if span else None
    if not status:
        return out
    if out["hidden"]:
        out["occluded"] = mean(status.get(i) == "occluded" for i in out["hidden"])
    claims = [share[i] for i in scored if vis[i] < 1 and status.get(i) in MEASURED
              and not math.isnan(share.get(i, NAN))]
    if claims:
        out["on_front"], out["on_front_max"] = mean(claims), max(claims)
    elif any(vis[i] < 1 for i in scored):
        out["on_front"] = out["on_front_max"] = 0.0  # covered, and never claimed any pixel
    if out["out"] is not None and out["out"] <= n - 2:
        found = [i for i in range(out["out"], n - 1) if status.get(i) in MEASURED and kept.get(i)]
        if found:
            out["refound"] = found[0]
            out["delay"] = found[0] - out["out"]
    return out


# ---- cost -----------------------------------------------------------------------------------------

def cost_numbers(run):
    """Per object count: the mean and median ms per frame of the MultiTracker (and, prefixed
    unlimited_, of the one with no budget) and of as many CSRTs (summed per frame); the statuses
    of the MultiTracker's results and the share of them that measured the object (followed); the
    frame's work (summed over objects) per frame."""
    by = collections.defaultdict(list)
    for r in run.cost:
        by[int(r["objects"])].append(r)
    out = {}
    for c, rows in sorted(by.items()):
        theirs = [float(r["csrt_ms"]) for r in rows if r["csrt_ms"] != ""]
        out[c] = {"csrt_ms": mean(theirs) if theirs else NAN,
                  "csrt_median": median(theirs) if theirs else NAN, "frames": len(rows)}
        for prefix in ("", "unlimited_"):
            ours = [float(r[prefix + "projtrack_ms"]) for r in rows
                    if r.get(prefix + "projtrack_ms", "") != ""]
            statuses = collections.Counter(s for r in rows
                                           for s in r.get(prefix + "statuses", "").split())
            out[c][prefix + "ms"] = mean(ours) if ours else NAN
            out[c][prefix + "ms_median"] = median(ours) if ours else NAN
            out[c][prefix + "work"] = [int(r[prefix + "work"]) for r in rows
                                       if r.get(prefix + "work", "") != ""]
            out[c][prefix + "statuses"] = statuses
            total = sum(statuses.values())
            out[c][prefix + "followed"] = (sum(statuses[s] for s in MEASURED) / total
                                           if total else NAN)
    return out
