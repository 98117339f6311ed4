#!/usr/bin/python3
"""Writes docs/real_footage.md from projtrack-real's measurements (./run bench --real).

Usage: bench/real/report.py DATA_DIR TRUTH_DIR DOC_DIR OUTPUT.md [--readme README.md]

Reads DATA_DIR/runs.csv, speed.csv, meta.json and DATA_DIR/frames/ (the element's overlay),
and TRUTH_DIR (bench/real/truth: the labels and outlines). Writes OUTPUT.md and, under DOC_DIR,
figures/, sheets/ and the data (runs.csv.gz, speed.csv, meta.json). With --readme, rewrites the
README's block between the real-footage markers with the summary. Every number and verdict is
computed here from the measurements; missing data reads "not measured".
"""
import argparse
import csv
import gzip
import json
import math
import os
import shutil
import statistics
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from report_kit import (MISSING, TARGET, fmt_num, fmt_pct, fmt_pct_g, fmt_res,  # noqa: E402
                        fmt_x, load_meta, missing, plt, span, verdict)

# OpenCV decodes the clips for the contact sheets: FFmpeg's complaints about the clips' H.264
# (harmless: the truth was labelled on the same decoded frames) would drown the progress.
os.environ.setdefault("OPENCV_FFMPEG_LOGLEVEL", "-8")
try:
    import cv2  # noqa: E402
except ImportError:  # contact sheets need python3-opencv; the tables do not
    cv2 = None

TRACKING = {"ok", "reached-border", "covers-frame"}
WITHIN = 0.25        # a frame is kept when the centroid is within this × √(true area)
AREA_TOLERANCE = 0.25  # and the area within this share of the true one
OVER = 2             # an area above this × the truth's, reported as tracked: a leak
PIECE = 0.5          # an area below this × the truth's: a piece of the object
NOTABLE_MISSES = 0.05  # a run missing on this share of a clip's frames or more is explained
SPANS = 0.9          # a reported box covering this share of the true box spans the object
STILL_SHARE = 0.005  # a reported box with fewer pixels changed over two frames is unchanged
SCENE_SHARE = 0.2  # and with fewer pixels apart from the clip's median frame, the background
README_BEGIN = "<!-- real-footage summary: written by bench/real/report.py -->"
README_END = "<!-- end of real-footage summary -->"

# Issue 13's targets: requirements, not results. Their goal texts are rendered from these.
GOAL_SEEDED_WITHIN = 0.97   # seeded: share of frames kept, worst clip, at least
GOAL_SEEDED_MEDIAN_PX = 5   # seeded: median centroid error, worst clip, at most (px)
GOAL_SEEDED_AREA = 0.90     # seeded: share of frames with the area within AREA_TOLERANCE
GOAL_SEEDED_OVER = 0        # seeded: frames tracked with an area above OVER × the truth's
GOAL_AUTO_WITHIN = 0.90     # no seed: share of frames kept, worst clip, at least
GOAL_STATIC = 0             # no seed: frames reporting a static region on the clip without one
GOAL_MOSSE = 2              # MOSSE's time ÷ projtrack's, at the clips' size, at least
GOAL_COPIES = 10            # projtrack's time ÷ a frame copy's at 1080p, at most


def fraction(x):
    """¼ for 0.25: how the docs write a share of √area."""
    return {0.25: "¼", 0.5: "½", 0.75: "¾"}.get(x, f"{x:g}·")


WITHIN_TEXT = f"{fraction(WITHIN)}√area"
TOLERANCE_TEXT = f"±{fmt_pct_g(AREA_TOLERANCE)}"


# ---- data ---------------------------------------------------------------------------------------

def load_runs(data_dir):
    runs = {}
    with open(os.path.join(data_dir, "runs.csv"), newline="") as f:
        for r in csv.DictReader(f):
            for k in ("frame", "measured", "x", "y", "width", "height", "has_pose", "push",
                      "acquired"):
                r[k] = int(r[k])
            for k in ("centroid_x", "centroid_y", "area", "position_x", "position_y", "depth",
                      "us", "moving_share", "scene_share"):
                r[k] = float(r[k])
            runs.setdefault((r["clip"], r["tracker"]), []).append(r)
    for rows in runs.values():
        rows.sort(key=lambda r: r["frame"])
    return runs


def load_truth(truth_dir, clip, data_dir=None):
    """A clip's truth: bench/real/truth's, or for a variant the harness's (DATA_DIR/truth)."""
    path = os.path.join(truth_dir, clip + ".csv")
    if data_dir and not os.path.exists(path):
        path = os.path.join(data_dir, "truth", clip + ".csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def load_outlines(truth_dir, clip):
    path = os.path.join(truth_dir, clip + "_outlines.csv.gz")
    out = {}
    if not os.path.exists(path):
        return out
    with gzip.open(path, "rt", newline="") as f:
        for r in csv.DictReader(f):
            pts = np.array([[int(v) for v in p.split(":")] for p in r["points"].split()],
                           np.int32)
            out.setdefault(int(r["frame"]), []).append((r["kind"], pts))
    return out


def labelled_clips(truth_dir):
    """The clips bench/real/truth labels: each must be measured for the seeded and no-seed
    targets."""
    if not os.path.isdir(truth_dir):
        return []
    return sorted(f[:-4] for f in os.listdir(truth_dir)
                  if f.endswith(".csv") and not f.endswith("_outlines.csv"))


# ---- metrics ------------------------------------------------------------------------------------

def centroid_error(r, t):
    if not r["measured"]:
        return math.inf
    return math.hypot(r["centroid_x"] - t["centroid_x"], r["centroid_y"] - t["centroid_y"])


def percentile(values, q):
    """The q-quantile (nearest rank): infinite when more than (1 - q) of the frames are lost."""
    if not values:
        return math.nan
    v = sorted(values)
    return v[min(len(v) - 1, max(0, math.ceil(q * len(v)) - 1))]


def worst(values, pick=min):
    """The worst of the clips' values; missing (NaN) when any clip's value is: min() over a list
    holding a NaN would quietly pass over it."""
    if not values or missing(*values):
        return math.nan
    return pick(values)


def kept(r, t):
    """Whether the frame counts as kept: centroid within WITHIN·√area and area within
    AREA_TOLERANCE of the truth's, measured on this frame."""
    return (r["measured"] and centroid_error(r, t) <= WITHIN * math.sqrt(t["area"]) and
            abs(r["area"] / t["area"] - 1) <= AREA_TOLERANCE)


def metrics(rows, truth):
    m = {"frames": len(rows)}
    m["tracked"] = sum(r["measured"] for r in rows)
    m["lost"] = sum(r["status"] == "lost" for r in rows)
    m["searching"] = sum(r["status"] == "searching" for r in rows)
    m["other"] = m["frames"] - m["tracked"] - m["lost"] - m["searching"]
    acquired = [r["frame"] for r in rows if r["acquired"]]
    m["reacquisitions"] = max(0, len(acquired) - 1)
    m["pushes"] = sum(r["push"] for r in rows)
    m["ms"] = statistics.median(r["us"] for r in rows) / 1000 if rows else math.nan
    still = [r for r in rows if r["measured"] and 0 <= r["moving_share"] < STILL_SHARE]
    static = [r for r in still if 0 <= r["scene_share"] < SCENE_SHARE]
    m["still"] = len(still)
    m["static"] = len(static)
    m["static_frames"] = [r["frame"] for r in static]
    if truth is None:
        return m
    errors, within, area_ok, over = [], 0, 0, 0
    for r in rows:
        t = truth[r["frame"]]
        e = centroid_error(r, t)
        errors.append(e)
        within += e <= WITHIN * math.sqrt(t["area"])
        if r["measured"]:
            area_ok += abs(r["area"] / t["area"] - 1) <= AREA_TOLERANCE
            over += r["area"] > OVER * t["area"]
    n = len(rows)
    m["errors"] = errors
    m["within"] = within / n if n else math.nan
    m["median"] = percentile(errors, 0.5)
    m["p90"] = percentile(errors, 0.9)
    m["area_ok"] = area_ok / n if n else math.nan
    m["over2"] = over
    m["misses"] = sum(not kept(r, truth[r["frame"]]) for r in rows)
    # Depth at each re-acquisition against the truth's change of size over the same frames:
    # 0 when the pointer's depth stays continuous with the object's real size.
    jumps = []
    for k in acquired[1:]:
        before = [r for r in rows if r["frame"] < k and r["has_pose"] and r["measured"]]
        now = rows[k] if rows[k]["frame"] == k else None
        if before and now and now["has_pose"] and before[-1]["depth"] > 0:
            j = before[-1]["frame"]
            reported = now["depth"] / before[-1]["depth"]
            true = math.sqrt(truth[k]["area"] / truth[j]["area"])
            jumps.append(abs(reported / true - 1))
    m["depth_jumps"] = jumps
    return m


# ---- formatting ---------------------------------------------------------------------------------

def fmt_px(x):
    if missing(x):
        return MISSING
    return "lost" if math.isinf(x) else f"{x:.1f}"


def fmt_share(x):
    """A share of frames: one decimal under 10 %, so a share just under a threshold does not
    read as on it, and a few misses do not read 0 %."""
    return fmt_pct(x, finer_under=0.1)


def fmt_ratio(x):
    """An area ratio: two decimals, or two significant digits under 0.1."""
    return f"{x:.2f}" if x >= 0.1 else f"{x:.2g}"


def plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def frames_text(frames):
    return ("frame " if len(frames) == 1 else "frames ") + ranges(frames)


def span_pct(values):
    return span(values, lambda v: f"{100 * v:.0f}", " %")


def ranges(frames, most=3):
    """'12–40, 50 and 3 more stretches' for sorted frame numbers."""
    if not frames:
        return "none"
    runs = []
    for f in frames:
        if runs and f == runs[-1][1] + 1:
            runs[-1][1] = f
        else:
            runs.append([f, f])
    longest = sorted(runs, key=lambda r: (-(r[1] - r[0]), r[0]))[:most]
    shown = [f"{a}–{b}" if b > a else f"{a}" for a, b in sorted(longest)]
    text = ", ".join(shown)
    if len(runs) > most:
        text += f" and {len(runs) - most} shorter stretch" + ("es" if len(runs) - most > 1 else "")
    return text


# ---- figures ------------------------------------------------------------------------------------

def plot_errors(clip, trackers, runs, truth, path):
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    scale = [math.sqrt(t["area"]) for t in truth]
    for ax, group in zip(axes, (True, False)):
        for name in trackers:
            if name.startswith("projtrack") != group:
                continue
            rows = runs[(clip, name)]
            e = [centroid_error(r, truth[r["frame"]]) / scale[r["frame"]] for r in rows]
            y = [min(v, 2.0) for v in e]  # lost frames drawn at the top
            ax.plot([r["frame"] for r in rows], y, lw=1, label=name.replace("projtrack ", ""))
        ax.axhline(WITHIN, color="k", ls="--", lw=0.8)
        ax.set_ylim(0, 2.05)
        ax.set_ylabel("centroid error / √area")
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, ncol=3, loc="upper right")
        ax.set_title(f"{clip}: {'projtrack' if group else 'peers'} (lost = 2, dashed = kept)",
                     fontsize=9)
    axes[-1].set_xlabel("frame")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def failure_frames(rows, truth, count):
    """Up to `count` frames where the tracker misses, spread over the clip."""
    bad = [r["frame"] for r in rows if not kept(r, truth[r["frame"]])]
    if len(bad) <= count:
        return bad
    return [bad[round(i * (len(bad) - 1) / (count - 1))] for i in range(count)]


def caption(r, t):
    c = miss_category(r, t)
    short = f"{c}, " if c and r["measured"] else ""
    if not r["measured"]:
        return f"{r['frame']}: {r['status']}"
    return (f"{r['frame']}: {short}area {fmt_ratio(r['area'] / t['area'])}x, "
            f"off {centroid_error(r, t):.0f} px")


def tile(img, text):
    cv2.rectangle(img, (0, 0), (img.shape[1], 34), (0, 0, 0), -1)
    cv2.putText(img, text, (8, 25), cv2.FONT_HERSHEY_SIMPLEX, 0.8, (255, 255, 255), 2)
    return cv2.resize(img, (320, 240))


def draw_truth(img, outlines):
    for kind, pts in outlines:
        cv2.polylines(img, [pts], True, (0, 255, 0) if kind == "outer" else (0, 160, 0), 2)


def write_sheet(tiles, path):
    cols = 4
    while len(tiles) % cols:
        tiles.append(np.zeros_like(tiles[0]))
    sheet = np.vstack([np.hstack(tiles[i:i + cols]) for i in range(0, len(tiles), cols)])
    cv2.imwrite(path, sheet, [cv2.IMWRITE_JPEG_QUALITY, 85])


def contact_sheet(frames_dir, rows, frames, truth, outlines, path):
    """The element's overlay on each frame, the truth's outline in green over it."""
    if cv2 is None or not frames:
        return False
    tiles = []
    for i in frames:
        path_i = os.path.join(frames_dir, f"{i:03d}.jpg")
        img = cv2.imread(path_i) if os.path.exists(path_i) else None
        if img is None:
            return False
        draw_truth(img, outlines.get(i, []))
        r = rows[i]
        tiles.append(tile(img, caption(r, truth[i]) if truth else f"{i}: {r['status']}"))
    write_sheet(tiles, path)
    return True


def decoded_frames(path, wanted):
    """{frame: BGR image} for the wanted frames of the clip at `path` (OpenCV decodes it, as the
    truth was labelled), or {} when it cannot be read."""
    if cv2 is None or not path or not os.path.exists(path) or not wanted:
        return {}
    cap = cv2.VideoCapture(path)
    out, i, last = {}, 0, max(wanted)
    while i <= last:
        ok, img = cap.read()
        if not ok:
            break
        if i in wanted:
            out[i] = img
        i += 1
    cap.release()
    return out


def data_sheet(images, rows, frames, truth, outlines, path):
    """What the run reported, drawn on the decoded frame: its box in red with its centroid as a
    cross; the true silhouette in green with its centroid as a dot."""
    if cv2 is None or not frames or any(i not in images for i in frames):
        return False
    tiles = []
    for i in frames:
        img = images[i].copy()
        draw_truth(img, outlines.get(i, []))
        t, r = truth[i], rows[i]
        cv2.circle(img, (round(t["centroid_x"]), round(t["centroid_y"])), 6, (0, 255, 0), -1)
        if r["measured"]:
            cv2.rectangle(img, (r["x"], r["y"]), (r["x"] + r["width"] - 1, r["y"] + r["height"] - 1),
                          (0, 0, 255), 2)
            cv2.drawMarker(img, (round(r["centroid_x"]), round(r["centroid_y"])), (0, 0, 255),
                           cv2.MARKER_CROSS, 22, 3)
        tiles.append(tile(img, caption(r, t)))
    write_sheet(tiles, path)
    return True


# ---- why it fails -------------------------------------------------------------------------------

CATEGORIES = [
    ("searching", "the element was searching: no track, nothing measured"),
    ("lost", "the element had lost the object or refused the estimate: nothing measured"),
    ("elsewhere", "the centroid lies outside the object's true box: the track is on something "
                  "else"),
    ("leak", f"the area is more than {OVER:g}× the truth's: the estimate ran out of the object"),
    ("larger", f"the area is {1 + AREA_TOLERANCE:g}–{OVER:g}× the truth's: the estimate takes in "
               "something beside the object"),
    ("part", f"the area is {PIECE:g}–{1 - AREA_TOLERANCE:g}× the truth's: the estimate measures "
             "part of the object"),
    ("piece", f"the area is under {PIECE:g}× the truth's: the estimate measures a piece of the "
              "object"),
    ("off", f"the area is within {TOLERANCE_TEXT} of the truth's but the centroid is off by more "
            f"than {WITHIN_TEXT}"),
]


def miss_category(r, t):
    """None on a kept frame; else the first category of CATEGORIES the frame's measurement fits."""
    if not r["measured"]:
        return "searching" if r["status"] == "searching" else "lost"
    if kept(r, t):
        return None
    near = centroid_error(r, t) <= WITHIN * math.sqrt(t["area"])
    inside = (t["x"] <= r["centroid_x"] < t["x"] + t["width"] and
              t["y"] <= r["centroid_y"] < t["y"] + t["height"])
    ratio = r["area"] / t["area"]
    if not near and not inside:
        return "elsewhere"
    if ratio > OVER:
        return "leak"
    if ratio > 1 + AREA_TOLERANCE:
        return "larger"
    if ratio < PIECE:
        return "piece"
    if ratio < 1 - AREA_TOLERANCE:
        return "part"
    return "off"


def direction(dx, dy):
    """'below and to the left of' from a displacement in image coordinates."""
    h = "to the right of" if dx > 0 else "to the left of"
    v = "below" if dy > 0 else "above"
    if abs(dx) >= 2 * abs(dy):
        return h
    if abs(dy) >= 2 * abs(dx):
        return v
    return f"{v} and {h}"


def box_cover(r, t):
    """The share of the true box that the reported box covers."""
    w = min(r["x"] + r["width"], t["x"] + t["width"]) - max(r["x"], t["x"])
    h = min(r["y"] + r["height"], t["y"] + t["height"]) - max(r["y"], t["y"])
    return max(0, w) * max(0, h) / (t["width"] * t["height"]) if t["width"] * t["height"] else 0


def past_box(r, t):
    """How far the reported box reaches past the true box on each side, px."""
    return {"left": t["x"] - r["x"], "right": r["x"] + r["width"] - t["x"] - t["width"],
            "above": t["y"] - r["y"], "below": r["y"] + r["height"] - t["y"] - t["height"]}


def explain(rows, truth):
    """What was measured on a run's missed frames, per category."""
    out = {"frames": len(rows), "missed": [], "by": {}}
    for r in rows:
        t = truth[r["frame"]]
        c = miss_category(r, t)
        if c is None:
            continue
        out["missed"].append(r["frame"])
        out["by"].setdefault(c, []).append((r, t))
    return out


def category_detail(key, pairs):
    """The measured figures behind one category of misses."""
    frames = [r["frame"] for r, _ in pairs]
    if key in ("searching", "lost"):
        reasons = {}
        for r, _ in pairs:
            d = r["detail"].split(";")[0].split("(")[0].strip() or r["status"]
            reasons[d] = reasons.get(d, 0) + 1
        top = sorted(reasons.items(), key=lambda kv: -kv[1])[:3]
        text = frames_text(frames)
        if any(d != key for d, _ in top):
            text += "; the element's reasons: " + "; ".join(f"\"{d}\" ({n})" for d, n in top)
        return text
    ratio = statistics.median(r["area"] / t["area"] for r, t in pairs)
    err = statistics.median(centroid_error(r, t) for r, t in pairs)
    rel = statistics.median(centroid_error(r, t) / math.sqrt(t["area"]) for r, t in pairs)
    near = sum(centroid_error(r, t) <= WITHIN * math.sqrt(t["area"]) for r, t in pairs)
    dx = statistics.median(r["centroid_x"] - t["centroid_x"] for r, t in pairs)
    dy = statistics.median(r["centroid_y"] - t["centroid_y"] for r, t in pairs)
    text = (f"{frames_text(frames)}; median area {fmt_ratio(ratio)}× the truth's, centroid "
            f"{err:.0f} px off ({rel:.2f}√area)")
    if near:
        text += f", within {WITHIN_TEXT} on {near} of them"
    if math.hypot(dx, dy) >= 1:
        text += f"; the centroid lies a median {math.hypot(dx, dy):.0f} px {direction(dx, dy)} " \
                "the true one"
    if key in ("part", "piece"):
        cover = statistics.median(box_cover(r, t) for r, t in pairs)
        text += f"; the reported box covers a median {fmt_pct(cover)} of the object's box"
        if cover >= SPANS:
            text += (": the estimate spans the object but counts less area than the object "
                     "has")
    if key in ("leak", "larger", "elsewhere"):
        sides = {s: statistics.median(past_box(r, t)[s] for r, t in pairs)
                 for s in ("left", "right", "above", "below")}
        side, px = max(sides.items(), key=lambda kv: kv[1])
        side = {"left": "to the left", "right": "to the right"}.get(side, side)
        if px > 0:
            text += (f"; the reported box reaches past the object's box most {side} "
                     f"(median {px:.0f} px)")
    return text


def seed_of(props):
    """(x, y) of inner-point-x/-y in an element's properties, or None."""
    got = {}
    for part in (props or "").split():
        k, _, v = part.partition("=")
        if k in ("inner-point-x", "inner-point-y"):
            try:
                got[k] = int(v)
            except ValueError:
                return None
    return (got["inner-point-x"], got["inner-point-y"]) if len(got) == 2 else None


def depth_inside(outlines, size, point):
    """The distance from `point` to the border of the silhouette drawn by `outlines` (px; 0
    outside it), and the silhouette's deepest distance, or None without OpenCV."""
    if cv2 is None or not outlines:
        return None
    w, h = size
    mask = np.zeros((h + 2, w + 2), np.uint8)
    for kind in ("outer", "hole"):
        for k, pts in outlines:
            if k == kind:
                cv2.fillPoly(mask, [pts], 1 if kind == "outer" else 0)
    d = cv2.distanceTransform(mask, cv2.DIST_L2, 5)
    x, y = point
    if not (0 <= x < d.shape[1] and 0 <= y < d.shape[0]):
        return 0.0, float(d.max())
    return float(d[y, x]), float(d.max())


# ---- the document -------------------------------------------------------------------------------

def variant_text(name, v):
    """How a variant was made, from the settings projtrack-real recorded in meta.json."""
    def shift(x, what):
        return f"{what} {abs(x):g} {'higher' if x > 0 else 'lower'}"

    texts = {
        "mirror": lambda: "left and right swapped",
        "dark": lambda: f"luma at {fmt_pct_g(v['luma'])} of its range, chroma at "
                        f"{fmt_pct_g(v['chroma'])}",
        "dim": lambda: f"a dim room: the light at {fmt_pct_g(v['light'])} (luma, and chroma's "
                       "distance from neutral)",
        "bright": lambda: f"luma × {v['gain']:g} {'+' if v['offset'] >= 0 else '−'} "
                          f"{abs(v['offset']):g}, highlights burnt out",
        "gamma": lambda: f"shadows lifted, luma through a gamma of {v['gamma']:g}",
        "warm": lambda: f"luma at {fmt_pct_g(v['luma'])}, {shift(v['cb'], 'Cb')}, "
                        f"{shift(v['cr'], 'Cr')}",
        "noise": lambda: f"Gaussian, σ {v['luma_sigma']:g} on luma, {v['chroma_sigma']:g} on "
                         "chroma",
        "fast": lambda: f"one frame in {v['step']:g}",
    }
    if v is None:
        return f"{name}: settings not recorded"
    try:
        return f"{name}: {texts[name]()}" if name in texts else f"{name}: {json.dumps(v)}"
    except (KeyError, TypeError, ValueError):
        return f"{name}: settings not recorded"


class Report:
    def __init__(self, data_dir, truth_dir, doc_dir):
        self.data_dir, self.truth_dir, self.doc_dir = data_dir, truth_dir, doc_dir
        self.runs = load_runs(data_dir)
        self.meta = load_meta(data_dir)
        self.speed = []
        speed_path = os.path.join(data_dir, "speed.csv")
        if os.path.exists(speed_path):
            with open(speed_path, newline="") as f:
                self.speed = list(csv.DictReader(f))
        self.clips = list(self.meta["clips"])
        self.truth = {c: load_truth(truth_dir, c, data_dir) for c in self.clips}
        self.variants = [c for c in self.clips if self.meta["clips"][c].get("variant")]
        self.clips = [c for c in self.clips if c not in self.variants]
        # The held clips: those with a truth, and every clip bench/real/truth labels, measured or
        # not.
        self.held = [c for c in self.clips if self.truth[c]]
        self.held += [c for c in labelled_clips(truth_dir) if c not in self.held]
        self.trackers = {c: [t for (cc, t) in self.runs if cc == c]
                         for c in self.clips + self.variants}
        self.m = {k: metrics(rows, self.truth.get(k[0])) for k, rows in self.runs.items()}
        self.lines = []
        self.default = self.default_method()
        self.explained = []

    def default_method(self):
        """The element's default method, as the harness read it from the element."""
        return self.meta["default_method"]

    def clip_meta(self, clip):
        return self.meta["clips"].get(clip, {})

    def size_text(self, clips):
        """'640×480' when the clips share a size, else each clip's."""
        sizes = {(self.clip_meta(c).get("width"), self.clip_meta(c).get("height")) for c in clips}
        sizes = {s for s in sizes if None not in s}
        if len(sizes) == 1:
            w, h = sizes.pop()
            return fmt_res(f"{w}x{h}")
        return "each clip's size" if sizes else "a size not recorded"

    def properties(self, clip, name):
        return self.clip_meta(clip).get("properties", {}).get(name)

    def ray_methods(self):
        """The paper's ray methods, from the table of methods projtrack-real recorded."""
        return [m["name"] for m in self.meta.get("methods", [])
                if m.get("family") == "rays" and m.get("from_paper")]

    def w(self, line=""):
        self.lines.append(line)

    def group(self, clip, name):
        rows = self.runs.get((clip, name))
        return rows[0]["group"] if rows else ""

    def table(self, clip):
        self.w(f"| tracker | kept (≤ {WITHIN_TEXT}) | median error px | p90 px | area "
               f"{TOLERANCE_TEXT} | area > {OVER:g}× (reported as tracked) | tracked / lost / "
               "searching | re-acquisitions | ms per frame |")
        self.w("|---|---|---|---|---|---|---|---|---|")
        for name in self.trackers[clip]:
            m = self.m[(clip, name)]
            box = " (box area)" if self.group(clip, name) == "box tracker" else ""
            self.w(f"| {name} | {fmt_pct(m['within'])} | {fmt_px(m['median'])} | "
                   f"{fmt_px(m['p90'])} | {fmt_pct(m['area_ok'])}{box} | {m['over2']} | "
                   f"{m['tracked']} / {m['lost']} / {m['searching']} | {m['reacquisitions']} | "
                   f"{fmt_num(m['ms'], 2)} |")
        self.w()
        cm = self.clip_meta(clip)
        size = fmt_res(f"{cm['width']}x{cm['height']}") if "width" in cm else "size not recorded"
        self.w(f"{len(self.truth[clip])} frames, {size}. "
               "Lost and searching frames count as misses in every column: their error is infinite "
               "(\"lost\" where a percentile falls on one).")
        if any(self.group(clip, n) == "projtrack seeded elsewhere" for n in self.trackers[clip]):
            self.w(f"\"projtrack seeded at x,y\": the default method ({self.default}) seeded at "
                   "the middle of each quarter of frame 0's true silhouette (about its centroid; "
                   "`bench/real/seeds.py`), where a user might click instead of its deepest point.")
        self.w()

    def variants_table(self):
        """The clips changed as footage we never tuned on would be: other light, noise,
        mirrored, faster."""
        name = f"projtrack {self.default}"
        self.w(f"| variant | projtrack seeded: kept | median px | area {TOLERANCE_TEXT} | "
               "no seed: kept | MOSSE: kept |")
        self.w("|---|---|---|---|---|---|")
        for clip in self.variants:
            m = self.m.get((clip, name))
            auto = self.m.get((clip, "projtrack no seed"))
            mosse = self.m.get((clip, "cvtracker MOSSE"))
            if not m:
                continue
            get = lambda x, k: x.get(k) if x else None  # noqa: E731
            self.w(f"| {clip} | {fmt_pct(get(m, 'within'))} | {fmt_px(get(m, 'median'))} | "
                   f"{fmt_pct(get(m, 'area_ok'))} | {fmt_pct(get(auto, 'within'))} | "
                   f"{fmt_pct(get(mosse, 'within'))} |")
        self.w()
        settings = self.meta.get("variants", {})
        hows = []
        for clip in self.variants:
            how = self.clip_meta(clip)["variant"]
            if how not in hows:
                hows.append(how)
        self.w("; ".join(variant_text(h, settings.get(h)) for h in hows) +
               ". The truth follows (mirrored, on the frames kept).")
        self.w()

    def pointer_table(self):
        self.w("| clip | run | pushes (all false: the clips hold none) | re-acquisitions | "
               "largest depth jump at a re-acquisition |")
        self.w("|---|---|---|---|---|")
        for clip in self.clips:
            for name in self.trackers[clip]:
                if not name.startswith("projtrack"):
                    continue
                m = self.m[(clip, name)]
                jumps = m.get("depth_jumps")
                jump = (f"{MISSING} (no truth)" if jumps is None else
                        "none" if not jumps else f"{100 * max(jumps):.0f} %")
                self.w(f"| {clip} | {name} | {m['pushes']} | {m['reacquisitions']} | {jump} |")
        self.w()
        self.w("A depth jump compares the pointer's depth just after a re-acquisition with the "
               "last depth before the loss, against the change of the true size over the same "
               "frames (0 % when depth stays continuous).")
        self.w()

    def static_table(self):
        self.w("| clip | run | frames reporting an object | of them, unchanged over two frames "
               "| of those, the scene's background: a static region |")
        self.w("|---|---|---|---|---|")
        for clip in self.clips:
            for name in self.trackers[clip]:
                if self.group(clip, name) != "projtrack no seed":
                    continue
                m = self.m[(clip, name)]
                self.w(f"| {clip} | {name} | {m['tracked']} | {m['still']} | {m['static']} |")
        self.w()
        levels = self.meta.get("changed_levels")
        levels = "a number of grey levels not recorded" if levels is None else \
            f"{levels:g} grey levels"
        self.w(f"Unchanged: a reported box in which fewer than {100 * STILL_SHARE:.1f} % of the "
               f"pixels changed by more than {levels} over the last two frames (a held "
               "object at rest, a walker's planted foot, or the background). A static region: "
               f"such a box of which fewer than {100 * SCENE_SHARE:.0f} % of the pixels differ by "
               f"more than {levels} from the clip's median frame (the scene without what "
               "passes through it), so the box shows the background.")
        self.w()

    def speed_section(self):
        self.w("## Speed")
        self.w()
        self.w(f"Per frame, medians over the clips at {self.size_text(self.held)}, every tracker "
               "run frame by frame in turn in one process (GstHarness for the elements; CamShift "
               "called directly, its HSV conversion included).")
        self.w()
        self.w("| clip | projtrack (default, seeded) ms | MOSSE ms | MOSSE ÷ projtrack |")
        self.w("|---|---|---|---|")
        ratios = []
        for clip in self.held:
            a = self.m.get((clip, f"projtrack {self.default}"), {}).get("ms")
            b = self.m.get((clip, "cvtracker MOSSE"), {}).get("ms")
            r = b / a if not missing(a, b) and a > 0 else math.nan
            ratios.append(r)
            self.w(f"| {clip} | {fmt_num(a, 2)} | {fmt_num(b, 2)} | {fmt_x(r)} |")
        self.w()
        big_res = sorted({r["resolution"] for r in self.speed})
        self.w(f"The clips scaled to {', '.join(map(fmt_res, big_res)) or MISSING}"
               ", the element (default method, seeded) beside a copy of the I420 frame, frame by "
               "frame in turn:")
        self.w()
        self.w("| clip | frame copy µs | projtrack µs | projtrack ÷ copy |")
        self.w("|---|---|---|---|")
        big = []
        for clip in self.held:
            rows = {}
            for r in self.speed:
                if r["clip"] == clip:
                    try:
                        rows[r["what"]] = float(r["median_us"])
                    except ValueError:
                        rows[r["what"]] = math.nan
            copy, ours = rows.get("frame copy", math.nan), rows.get("projtrack", math.nan)
            x = ours / copy if not missing(copy, ours) and copy > 0 else math.nan
            big.append(x)
            self.w(f"| {clip} | {fmt_num(copy)} | {fmt_num(ours)} | {fmt_x(x)} |")
        self.w()
        self.speed_ratios = (worst(ratios, min), worst(big, max), big_res)

    def targets(self):
        """Issue 13's targets, judged on the measurements. A held clip without its run, or a
        run whose number is missing, makes the target "not measured"."""
        name = f"projtrack {self.default}"
        seeded = [self.m.get((c, name)) for c in self.held]
        auto = [self.m.get((c, "projtrack no seed")) for c in self.held]

        def of(ms, k, pick=min):
            return worst([m[k] if m else math.nan for m in ms], pick)

        # The target is the clip where nobody holds an object: vtest (no truth). The
        # held clips' counts are in the table below, for what they are: moments the hand rests.
        no_truth = [c for c in self.clips if not self.truth[c]]
        statics = [float(self.m[(c, "projtrack no seed")]["static"])
                   if (c, "projtrack no seed") in self.m else math.nan for c in no_truth]
        static = sum(statics) if no_truth and not missing(*statics) else math.nan
        over = [float(m["over2"]) if m else math.nan for m in seeded]
        mosse_x, copy_x, big_res = getattr(self, "speed_ratios", (math.nan, math.nan, []))
        size = self.size_text(self.held)
        big = ", ".join(map(fmt_res, big_res)) or "a size not recorded"
        rows = [
            (f"seeded: frames within {WITHIN_TEXT} (worst clip)",
             f"≥ {fmt_pct(GOAL_SEEDED_WITHIN)}", of(seeded, "within"),
             lambda v: v >= GOAL_SEEDED_WITHIN, fmt_pct),
            ("seeded: median centroid error (worst clip)", f"≤ {GOAL_SEEDED_MEDIAN_PX:g} px",
             of(seeded, "median", max), lambda v: v <= GOAL_SEEDED_MEDIAN_PX,
             lambda v: fmt_px(v) + (" px" if math.isfinite(v) else "")),
            (f"seeded: area within {TOLERANCE_TEXT} (worst clip)",
             f"≥ {fmt_pct(GOAL_SEEDED_AREA)}", of(seeded, "area_ok"),
             lambda v: v >= GOAL_SEEDED_AREA, fmt_pct),
            (f"seeded: frames tracked with area > {OVER:g}× truth (every held clip)",
             f"{GOAL_SEEDED_OVER:g}", sum(over) if not missing(*over) and over
             else math.nan, lambda v: v <= GOAL_SEEDED_OVER, fmt_num),
            (f"no seed: frames within {WITHIN_TEXT} (worst clip)",
             f"≥ {fmt_pct(GOAL_AUTO_WITHIN)}", of(auto, "within"),
             lambda v: v >= GOAL_AUTO_WITHIN, fmt_pct),
            ("no seed: frames reporting a static region, on the clip with no held object",
             f"{GOAL_STATIC:g}", static, lambda v: v <= GOAL_STATIC, fmt_num),
            (f"speed: MOSSE ÷ projtrack at {size} (worst clip)", f"≥ {GOAL_MOSSE:g}×", mosse_x,
             lambda v: v >= GOAL_MOSSE, fmt_x),
            (f"speed: projtrack ÷ frame copy at {big} (worst clip)", f"≤ {GOAL_COPIES:g}×",
             copy_x, lambda v: v <= GOAL_COPIES, fmt_x),
        ]
        self.w("| target | goal | measured | verdict |")
        self.w("|---|---|---|---|")
        self.verdicts = []
        for what, goal, value, ok, fmt in rows:
            v = verdict([value], ok, words=TARGET)
            self.verdicts.append((what, goal, value, v, fmt))
            shown = MISSING if missing(value) else fmt(value)
            self.w(f"| {what} | {goal} | {shown} | {v} |")
        missing_clips = [c for c in self.held if c not in self.clips]
        if missing_clips:
            self.w()
            self.w("Not in this run, though bench/real/truth labels them: "
                   f"{', '.join(missing_clips)}: every target over the held clips reads "
                   "\"not measured\".")
        self.w()

    # --- why it fails ---
    def misses_table(self):
        """Every projtrack run on a clip with a truth that misses: its misses by category."""
        keys = [k for k, _ in CATEGORIES]
        self.w("| clip | run | misses | " + " | ".join(keys) + " |")
        self.w("|---|---|---|" + "---|" * len(keys))
        clean = []
        for clip in self.clips + self.variants:
            if not self.truth.get(clip):
                continue
            for name in self.trackers[clip]:
                if not name.startswith("projtrack"):
                    continue
                x = explain(self.runs[(clip, name)], self.truth[clip])
                if not x["missed"]:
                    clean.append(f"{clip} {name.replace('projtrack ', '')}")
                    continue
                counts = [len(x["by"].get(k, [])) for k in keys]
                self.w(f"| {clip} | {name} | {len(x['missed'])} of {x['frames']} "
                       f"({fmt_share(len(x['missed']) / x['frames'])}) | "
                       + " | ".join(str(n) if n else "" for n in counts) + " |")
        self.w()
        if clean:
            self.w("No miss on any frame: " + ", ".join(clean) + ".")
            self.w()

    def why(self, clip, name, sheet, legend):
        rows = self.runs[(clip, name)]
        t = self.truth[clip]
        x = explain(rows, t)
        n, k = x["frames"], len(x["missed"])
        props = self.properties(clip, name)
        self.w(f"### {clip}: {name}")
        self.w()
        head = f"Run with `{props}`" if props is not None else "Its properties were not recorded"
        if not k:
            self.w(f"{head}: it keeps the object on every frame.")
            self.w()
            return
        self.w(f"{head}: it misses on {k} of {n} frames ({fmt_share(k / n)}).")
        self.w()
        first = rows[0]
        if first["frame"] == 0:
            if first["measured"]:
                self.w(f"- On frame 0 it reports {fmt_ratio(first['area'] / t[0]['area'])}× the true "
                       f"area, its centroid {centroid_error(first, t[0]):.0f} px from the "
                       "true one.")
            else:
                self.w(f"- On frame 0 it reports nothing measured (status {first['status']}).")
        seed = seed_of(props)
        if seed is None and self.group(clip, name) == "projtrack seeded":  # older data
            seed = (int(t[0]["inner_x"]), int(t[0]["inner_y"]))
        elif seed is None and name.startswith("projtrack seeded at "):
            try:
                seed = tuple(int(v) for v in name.rsplit(" ", 1)[1].split(","))
            except ValueError:
                seed = None
        cm = self.clip_meta(clip)
        outlines = load_outlines(self.truth_dir, clip).get(0, [])
        depth = depth_inside(outlines, (cm.get("width", 0), cm.get("height", 0)), seed) \
            if seed and "width" in cm else None
        if depth and depth[0] < depth[1] - 1:
            self.w(f"- Its seed ({seed[0]},{seed[1]}) lies {depth[0]:.0f} px inside frame 0's "
                   f"true silhouette (0: outside it); the silhouette's deepest point lies "
                   f"{depth[1]:.0f} px inside.")
        acquired = [r["frame"] for r in rows if r["acquired"]]
        if acquired and (acquired[0] > 0 or len(acquired) > 1):
            self.w(f"- Tracks start on frame{'s' if len(acquired) > 1 else ''} "
                   f"{ranges(acquired, 5)}.")
        self.w(f"- Missed frames: {ranges(x['missed'])}.")
        for key, text in CATEGORIES:
            pairs = x["by"].get(key)
            if pairs:
                self.w(f"- {plural(len(pairs), 'frame')}, {text}: {category_detail(key, pairs)}.")
        self.w()
        if sheet:
            self.w(f"![{clip}, {name}: where it misses]({sheet})")
            self.w()
            self.w(legend)
            self.w()
        elif k:
            self.w("No contact sheet: the frames to draw on were not found (the element's "
                   "overlay, or the clip's file recorded in meta.json).")
            self.w()

    def why_section(self, rel):
        self.w("## Why it fails")
        self.w()
        self.w(f"A frame is a miss when nothing was measured on it, the centroid is off by more "
               f"than {WITHIN_TEXT}, or the area is off by more than {TOLERANCE_TEXT}. Each miss "
               "is put in the first category its measurement fits:")
        self.w()
        for key, text in CATEGORIES:
            self.w(f"- **{key}**: {text};")
        self.lines[-1] = self.lines[-1][:-1] + "."
        self.w()
        self.misses_table()
        self.w(f"Below, every run on the clips as decoded that misses on at least "
               f"{fmt_pct(NOTABLE_MISSES)} of the frames, and the default method at the deepest "
               "seed whatever it misses, with what was measured on its missed frames and a "
               "contact sheet of them.")
        self.w()
        overlay = ("Each tile is the element's own overlay (draw=true) with the true silhouette "
                   "in green; the caption gives the miss's category, the reported area as a "
                   "multiple of the true one and how far the centroid is off, or the status "
                   "when nothing was measured.")
        drawn = ("Each tile is the decoded frame with what the run reported drawn over it: its "
                 "box in red, its centroid as a red cross; the true silhouette in green, its "
                 "centroid as a green dot. The caption gives the miss's category, the reported "
                 "area as a multiple of the true one and how far the centroid is off, or the "
                 "status when nothing was measured.")
        default = f"projtrack {self.default}"
        for clip in self.clips:
            if not self.truth[clip]:
                continue
            chosen = []
            for name in self.trackers[clip]:
                if not name.startswith("projtrack"):
                    continue
                m = self.m[(clip, name)]
                if name == default or (m["frames"] and m["misses"] / m["frames"] >= NOTABLE_MISSES):
                    chosen.append(name)
            overlays = {default: "seeded", "projtrack no seed": "no-seed"}
            picks = {name: failure_frames(self.runs[(clip, name)], self.truth[clip],
                                          12 if name == default else 8) for name in chosen}
            need = {f for fr in picks.values() for f in fr}
            images = decoded_frames(self.clip_meta(clip).get("path"), need)
            outlines = load_outlines(self.truth_dir, clip)
            for name in chosen:
                rows, frames = self.runs[(clip, name)], picks[name]
                slug = name.replace("projtrack ", "").replace(" ", "-").replace(",", "-")
                sheet = f"sheets/{clip}-{slug}-misses.jpg"
                path = os.path.join(self.doc_dir, sheet)
                made, legend = False, overlay
                if name in overlays:
                    made = contact_sheet(os.path.join(self.data_dir, "frames", clip,
                                                      overlays[name]), rows, frames,
                                         self.truth[clip], outlines, path)
                if not made:
                    made, legend = data_sheet(images, rows, frames, self.truth[clip], outlines,
                                              path), drawn
                self.why(clip, name, f"{rel}/{sheet}" if made else None, legend)
                self.explained.append((clip, name))

    def write(self, path):
        os.makedirs(os.path.join(self.doc_dir, "figures"), exist_ok=True)
        os.makedirs(os.path.join(self.doc_dir, "sheets"), exist_ok=True)
        rel = os.path.relpath(self.doc_dir, os.path.dirname(os.path.abspath(path)))
        self.w("# Real footage")
        self.w()
        self.w("<!-- Generated by bench/real/report.py from `./run bench --real`: do not edit. -->")
        self.w()
        clips = ", ".join(f"{c} ({v['frames']} frames, {v['width']}×{v['height']})"
                          for c, v in self.meta["clips"].items())
        self.w(f"Measured {self.meta['measured']} on {self.meta['cpu']} "
               f"({self.meta['cores']} cores), OpenCV {self.meta['opencv']}, "
               f"{self.meta['gstreamer']}. Clips from Debian's `opencv-doc`: {clips}.")
        self.w()
        no_seed = next((self.properties(c, "projtrack no seed") for c in self.clips
                        if self.properties(c, "projtrack no seed") is not None), None)
        self.w("The truth (bench/real/truth/, made by colour segmentation, never from projtrack; "
               "see bench/real/truth/README.md) gives each frame's silhouette: the cup without the "
               "fingers in front of it, the whole box with its printed pictures. projtrack runs "
               "with every method, seeded at the point of frame 0's true silhouette farthest "
               "from its border, and with no seed ("
               + (f"`{no_seed}`" if no_seed is not None else "its properties not recorded")
               + "); the box trackers start from frame 0's true box and report a box: their "
               "area is the box's. " + self.camshift_text())
        self.w()
        self.w(f"## Targets (issue 13), default method `{self.default}`")
        self.w()
        # The speed section is computed first (the targets need it) and printed further down.
        saved = self.lines
        self.lines = []
        self.speed_section()
        speed_lines = self.lines
        self.lines = saved
        self.targets()
        for clip in self.held:
            self.w(f"## {clip}")
            self.w()
            if clip not in self.clips:
                self.w(f"{MISSING}: this run holds no data for {clip}.")
                self.w()
                continue
            self.table(clip)
            fig = f"figures/{clip}-error.png"
            plot_errors(clip, self.trackers[clip], self.runs, self.truth[clip],
                        os.path.join(self.doc_dir, fig))
            self.w(f"![{clip}: centroid error over time]({rel}/{fig})")
            self.w()
        if self.variants:
            self.w("## The same clips as other footage would show them")
            self.w()
            self.variants_table()
        self.w("## No seed: is a static region ever taken for the object?")
        self.w()
        self.static_table()
        self.w("## The 3D pointer")
        self.w()
        self.pointer_table()
        self.lines += speed_lines
        self.why_section(rel)
        for clip in self.clips:
            key = (clip, "projtrack no seed")
            if key not in self.m or not self.m[key]["static_frames"]:
                continue
            frames = self.m[key]["static_frames"]
            pick = [frames[round(i * (len(frames) - 1) / 7)] for i in range(8)] \
                if len(frames) > 8 else frames
            sheet = f"sheets/{clip}-static.jpg"
            if contact_sheet(os.path.join(self.data_dir, "frames", clip, "no-seed"),
                             self.runs[key], pick, self.truth[clip], {},
                             os.path.join(self.doc_dir, sheet)):
                self.w(f"### {clip}, no seed: static regions reported")
                self.w()
                self.w(f"![{clip}: static regions taken for the object]({rel}/{sheet})")
                self.w()
        with open(path, "w") as f:
            f.write("\n".join(self.lines).rstrip() + "\n")

    def camshift_text(self):
        c = self.meta.get("camshift")
        if not c:
            return "CamShift's histogram was not recorded."
        try:
            kind = c["histogram"]
            bins = (f"{c['hue_bins']} hue × {c['saturation_bins']} saturation bins"
                    if kind == "hue-saturation" else f"{c.get('hue_bins', '?')} hue bins")
            return (f"OpenCV's CamShift runs on the back projection of a {kind} histogram "
                    f"({bins}) of frame 0's true box, counting only pixels of saturation ≥ "
                    f"{c['saturation_min']} and value ≥ {c['value_min']} (camshiftdemo's mask; "
                    "camshiftdemo itself uses a hue histogram alone).")
        except KeyError:
            return "CamShift's histogram was not fully recorded."

    def others_summary(self):
        """The README's line on the paper's ray methods and the other seeds, from the data."""
        out = []
        rays = self.ray_methods()
        if not rays:
            out.append("The paper's ray methods: not measured (the table of methods was not "
                       "recorded).")
        else:
            def over_rays(c, key):
                return span_pct([self.m.get((c, f"projtrack {r}"), {}).get(key, math.nan)
                                 for r in rays])
            kept_ = ", ".join(f"{c} {over_rays(c, 'within')}" for c in self.held)
            area = ", ".join(f"{c} {over_rays(c, 'area_ok')}" for c in self.held)
            out.append(f"The paper's ray methods ({', '.join(rays)}), seeded alike, keep the "
                       f"object on {kept_} of the frames, with the area within {TOLERANCE_TEXT} "
                       f"on {area}.")
        parts = []
        for c in self.held:
            names = [n for n in self.trackers.get(c, [])
                     if self.group(c, n) == "projtrack seeded elsewhere"]
            if not names:
                parts.append(f"{c} {MISSING}")
                continue
            within = [self.m[(c, n)]["within"] for n in names]
            area = [self.m[(c, n)]["area_ok"] for n in names]
            parts.append(f"{c} {span_pct(within)} (area within {TOLERANCE_TEXT}: "
                         f"{span_pct(area)})")
        out.append(f"Seeded instead at the middle of each quarter of frame 0's true silhouette, "
                   f"the default method keeps it on {'; '.join(parts)}; "
                   "[docs/real_footage.md](docs/real_footage.md#why-it-fails) says why it misses.")
        return out

    def summary(self):
        """The README's lines: the verdicts, as measured."""
        out = [README_BEGIN]
        met = sum(v[3] == "**met**" for v in self.verdicts)
        unmeasured = sum(v[3] == MISSING for v in self.verdicts)
        out.append(f"On real footage (opencv-doc's cup, box and walking people; "
                   f"[docs/real_footage.md](docs/real_footage.md)), the element with its default "
                   f"method meets {met} of its {len(self.verdicts)} targets"
                   + (f" ({unmeasured} not measured)" if unmeasured else "") + ":")
        out.append("")
        for what, goal, value, v, fmt in self.verdicts:
            shown = MISSING if missing(value) else fmt(value)
            out.append(f"- {what}: {shown} (goal {goal}): {v.strip('*')}")
        out.append("")
        for clip in self.held:
            ours = self.m.get((clip, f"projtrack {self.default}"))
            peers = [(self.m[(clip, t)]["within"], t) for t in self.trackers.get(clip, [])
                     if self.group(clip, t) == "box tracker"
                     and not missing(self.m[(clip, t)]["within"])]
            if not ours or not peers:
                out.append(f"On {clip}, projtrack (seeded) beside the box trackers: {MISSING}.")
                continue
            best, name = max(peers)
            out.append(f"On {clip}, projtrack (seeded) keeps the object on {fmt_pct(ours['within'])}"
                       f" of the frames; the best box tracker, {name}, on {fmt_pct(best)}.")
        out += self.others_summary()
        out.append(README_END)
        return "\n".join(out)


def rewrite_readme(path, block):
    text = open(path).read()
    if README_BEGIN not in text or README_END not in text:
        sys.exit(f"bench/real/report.py: {path} has no real-footage markers")
    head, rest = text.split(README_BEGIN, 1)
    _, tail = rest.split(README_END, 1)
    with open(path, "w") as f:
        f.write(head + block + tail)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("data_dir")
    ap.add_argument("truth_dir")
    ap.add_argument("doc_dir")
    ap.add_argument("output")
    ap.add_argument("--readme")
    a = ap.parse_args()
    report = Report(a.data_dir, a.truth_dir, a.doc_dir)
    report.write(a.output)
    if os.path.abspath(a.doc_dir) != os.path.abspath(a.data_dir):
        for name in ("speed.csv", "meta.json"):
            shutil.copy(os.path.join(a.data_dir, name), os.path.join(a.doc_dir, name))
        with open(os.path.join(a.data_dir, "runs.csv"), "rb") as src, \
                gzip.GzipFile(os.path.join(a.doc_dir, "runs.csv.gz"), "wb", mtime=0) as dst:
            shutil.copyfileobj(src, dst)
    if a.readme:
        rewrite_readme(a.readme, report.summary())


if __name__ == "__main__":
    main()
