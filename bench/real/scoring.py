"""How a run on real footage is scored, from projtrack-real's runs.csv and the
entry's truth (DATA/truth/<entry>.csv, written by prepare.py).

A frame is **kept** when the run measured the object on it, its centroid lies within
WITHIN·√(true area) of the true one **and** its area lies within [AREA_MIN, AREA_MAX]× the true
area; **kept, centroid only** drops the area condition. Only frames where the
object is in view (true area > 0) are scored; what a run reports on the others is counted apart.
A frame of the truth the run has no row for counts as a miss. Anything not measured (a missing
row, a NaN) never passes.
"""
import csv
import math
import os
import statistics

TRACKING = {"ok", "reached-border", "covers-frame"}
WITHIN = 0.25          # the centroid within this × √(true area)
AREA_MIN, AREA_MAX = 0.5, 2.0  # and the area within these × the truth's
AREA_TOLERANCE = 0.25  # "area within ±25 %"
STILL_SHARE = 0.005  # a reported box with fewer pixels changed over two frames is unchanged
SCENE_SHARE = 0.2    # and with fewer pixels apart from the clip's median frame: the background

INTS = ("frame", "measured", "x", "y", "width", "height", "has_pose", "push", "acquired")
FLOATS = ("centroid_x", "centroid_y", "area", "position_x", "position_y", "depth", "us",
          "moving_share", "scene_share", "work")


def load_runs(data_dir):
    """{(entry, tracker): [row]} sorted by frame."""
    runs = {}
    with open(os.path.join(data_dir, "runs.csv"), newline="") as f:
        for r in csv.DictReader(f):
            for k in INTS:
                r[k] = int(r[k])
            for k in FLOATS:
                r[k] = float(r[k]) if r.get(k, "") != "" else math.nan
            runs.setdefault((r["clip"], r["tracker"]), []).append(r)
    for rows in runs.values():
        rows.sort(key=lambda r: r["frame"])
    return runs


def load_truth(data_dir, entry):
    """The entry's truth rows (None for an empty field: not in view), or None."""
    path = os.path.join(data_dir, "truth", entry + ".csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return [{k: (float(v) if v != "" else None) for k, v in r.items()}
                for r in csv.DictReader(f)]


def in_view(t):
    return bool(t and t["area"])


def centroid_error(r, t):
    """px; infinite when nothing was measured (or no row)."""
    if not r or not r["measured"]:
        return math.inf
    e = math.hypot(r["centroid_x"] - t["centroid_x"], r["centroid_y"] - t["centroid_y"])
    return math.inf if math.isnan(e) else e


def near(r, t):
    """Kept by the centroid alone: within WITHIN·√area (NaN and missing never pass)."""
    return centroid_error(r, t) <= WITHIN * math.sqrt(t["area"])


def area_ratio(r, t):
    return r["area"] / t["area"] if r and r["measured"] else math.nan


def kept(r, t):
    """Kept: near, and the area within [AREA_MIN, AREA_MAX]× the truth's."""
    return near(r, t) and AREA_MIN <= area_ratio(r, t) <= AREA_MAX


def median_or_inf(values):
    """The median; infinite when at least half are (lost frames)."""
    return statistics.median(values) if values else math.nan


def score(rows, truth):
    """The measures of one run against its entry's truth."""
    by = {r["frame"]: r for r in rows}
    n = len(truth)
    view = [i for i in range(n) if in_view(truth[i])]
    m = {"frames": n, "in_view": len(view), "rows": len(rows),
         "missing": sum(i not in by for i in range(n))}
    rel, kept_new, kept_old, area_ok = [], 0, 0, 0
    for i in view:
        r, t = by.get(i), truth[i]
        rel.append(centroid_error(r, t) / math.sqrt(t["area"]))
        kept_old += near(r, t)
        kept_new += kept(r, t)
        area_ok += abs(area_ratio(r, t) - 1) <= AREA_TOLERANCE
    k = len(view)
    m["kept"] = kept_new / k if k else math.nan
    m["kept_old"] = kept_old / k if k else math.nan
    m["median_rel"] = median_or_inf(rel)
    m["area_ok"] = area_ok / k if k else math.nan
    out = [by.get(i) for i in range(n) if not in_view(truth[i])]
    m["out_of_view"] = len(out)
    m["out_reported"] = sum(1 for r in out if r and r["measured"])
    m["missed_frames"] = [i for i in view if not kept(by.get(i), truth[i])]
    return m


def run_stats(rows):
    """What a run says whatever the truth: statuses, time, work, static regions."""
    m = {"tracked": sum(r["measured"] for r in rows),
         "lost": sum(r["status"] == "lost" for r in rows),
         "searching": sum(r["status"] == "searching" for r in rows),
         "over_budget": sum(r["status"] == "over-budget" for r in rows),
         "ms": statistics.median(r["us"] for r in rows) / 1000 if rows else math.nan}
    still = [r for r in rows if r["measured"] and 0 <= r["moving_share"] < STILL_SHARE]
    static = [r for r in still if 0 <= r["scene_share"] < SCENE_SHARE]
    m["still"], m["static"] = len(still), len(static)
    m["static_frames"] = [r["frame"] for r in static]
    return m


# ---- why a frame is missed ----------------------------------------------------------------------

CATEGORIES = [
    ("missing", "the run has no row for the frame (cut short)"),
    ("searching", "the element was searching: nothing measured"),
    ("lost", "the element had lost the object or refused the estimate: nothing measured"),
    ("elsewhere", "the centroid lies outside the object's true box: the track is on something "
                  "else"),
    ("leak", f"the area is more than {AREA_MAX:g}× the truth's"),
    ("piece", f"the area is under {AREA_MIN:g}× the truth's: a piece of the object"),
    ("off", f"the area is within {AREA_MIN:g}–{AREA_MAX:g}× but the centroid is off by more than "
            "¼√area"),
]


def miss_category(r, t):
    """None on a kept frame; else the first category its measurement fits."""
    if r is None:
        return "missing"
    if not r["measured"]:
        return "searching" if r["status"] == "searching" else "lost"
    if kept(r, t):
        return None
    inside = (t["x"] <= r["centroid_x"] < t["x"] + t["width"] and
              t["y"] <= r["centroid_y"] < t["y"] + t["height"])
    ratio = area_ratio(r, t)
    if not near(r, t) and not inside:
        return "elsewhere"
    if not ratio <= AREA_MAX:
        return "leak"
    if ratio < AREA_MIN:
        return "piece"
    return "off"


def categories(rows, truth):
    """{category: [frame]} over the in-view frames a run misses."""
    by = {r["frame"]: r for r in rows}
    out = {}
    for i, t in enumerate(truth):
        if in_view(t):
            c = miss_category(by.get(i), t)
            if c:
                out.setdefault(c, []).append(i)
    return out
