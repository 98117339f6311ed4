"""What bench/speed/report.py's parts share: the names of the contenders, the targets (issue 6's
and 16's: requirements, not results), reading speed.csv and the helpers over its rows."""
import csv
import math
import os
import statistics

from report_kit import DASH, MISSING, frame_size, load_meta, missing

COPY, HARNESS = "frame copy", "harness alone (identity)"
PEER_CV, PEER_MOSSE = "cv::Canny + cv::floodFill", "cvtracker MOSSE"
ELEMENT = "projtrack element default"
BLUR, CV_BLUR, CANNY, CV_CANNY = "projtrack box blur", "cv::blur", "projtrack Canny", "cv::Canny"

# The targets (issue 6's): requirements, not results.
T1_COPIES = 10        # 1: the element costs at most this many frame copies (1080p)
T2_CANNY_FLOOD = 5    # 2: at least this many times faster than Canny + floodFill (1080p)
T3_MOSSE = 2          # 3: at least this many times faster than MOSSE (640×480)
T4_GROWTH = 2         # 4: the same object in the larger frame costs less than this many times more
T5_FLAT_KIB = 1024    # 5: resident memory grows by less than this over the long run
T6_STREAMS, T6_FPS = 8, 30  # 6: this many concurrent 640×480 streams at this rate each
# Issue 16's, bounded work, at 1080p:
T7_RATIO, T7_MS = 3, 10  # 7: defaults, adversarial content: worst ≤ this × ordinary, ≤ this ms
T8_MS = 50               # 8: any valid settings: the worst frame ≤ this many ms
T9_MS = 50               # 9: set_state(NULL) during a heavy frame returns within this many ms
BOUNDED_RES = "1920x1080"


def load(data_dir):
    rows = []
    with open(os.path.join(data_dir, "speed.csv")) as f:
        for r in csv.DictReader(f):
            r["value"] = float(r["value"])
            rows.append(r)
    return rows, load_meta(data_dir)


def value(rows, section, clip, res, what, key):
    """The measurement, or None when it was not taken (or is not a number)."""
    for r in rows:
        if (r["section"], r["clip"], r["resolution"], r["what"], r["key"]) == (
                section, clip, res, what, key):
            return None if math.isnan(r["value"]) else r["value"]
    return None


def fmt_us(us):
    """A time in µs, or in ms from 1 ms on; a dash when not measured."""
    if us is None:
        return DASH
    return f"{us / 1000:.2f} ms" if us >= 1000 else f"{us:.0f} µs"


def megapixels(res):
    w, h = frame_size(res)
    return f"{w * h / 1e6:.1f} Mpx"


def size_rows(rows):
    """{(res, method): [(object_px, us)]} sorted by size."""
    out = {}
    for r in rows:
        if r["section"] != "size":
            continue
        px = int(r["key"].rsplit("_", 1)[1])
        out.setdefault((r["resolution"], r["what"]), []).append((px, r["value"]))
    for k in out:
        out[k].sort()
    return out


def growth_by_method(sizes, methods):
    """Per method: the median over object sizes of (cost in the larger frame ÷ in the smaller),
    the resolutions, and the frames' pixel ratio."""
    resolutions = sorted({res for res, _ in sizes}, key=lambda r: frame_size(r)[0])
    if len(resolutions) < 2:
        return {}, resolutions, None
    small, large = resolutions[0], resolutions[-1]
    pixels = [math.prod(frame_size(r)) for r in (small, large)]
    growth = {}
    for m in methods:
        a, b = dict(sizes.get((small, m), [])), dict(sizes.get((large, m), []))
        common = sorted(set(a) & set(b))
        if common:
            growth[m] = (statistics.median(b[p] / a[p] for p in common), common, a, b)
    return growth, resolutions, pixels[1] / pixels[0]


def edge_cases(rows):
    """Our blur and Canny against OpenCV's per region: [(object_px, region, frame, {what: us},
    blur ratio, Canny ratio)], tracker regions first (by object size), whole frames last."""
    out = []
    for r in rows:
        if r["section"] != "edge_region":
            continue
        res, region = r["resolution"], r["what"]
        us = {w: value(rows, "edge_stages", r["clip"], res, w, region)
              for w in [BLUR, CV_BLUR, CANNY, CV_CANNY]}
        out.append((r["value"], region.replace("region_", ""), res, us,
                    value(rows, "edge_ratio", r["clip"], res, f"{CV_BLUR} / {BLUR}", region),
                    value(rows, "edge_ratio", r["clip"], res, f"{CV_CANNY} / {CANNY}", region)))
    return sorted(out, key=lambda c: (c[0] == 0, c[0], math.prod(frame_size(c[2]))))


def speed_phrase(ratios):
    """How much faster ours is, from OpenCV's time ÷ ours over some regions."""
    ratios = [r for r in ratios if not missing(r)]
    if not ratios:
        return MISSING
    lo, hi = min(ratios), max(ratios)
    if lo >= 1:
        return f"{lo:.1f}×" + ("" if f"{lo:.1f}" == f"{hi:.1f}" else f"–{hi:.1f}×") + " faster"
    if hi < 1:
        return f"{1 / hi:.1f}×" + ("" if f"{hi:.1f}" == f"{lo:.1f}" else f"–{1 / lo:.1f}×") + \
            " slower"
    return f"from {1 / lo:.1f}× slower to {hi:.1f}× faster"


def streams(rows, n):
    """The concurrent-streams run of n streams: frames tracked per second and its counts."""
    what = f"{n} stream" + ("" if n == 1 else "s")
    keys = ["fps", "frames_pushed", "pushes_refused", "frames_tracked", "messages", "timeouts",
            "timeout_s", "errors"]
    s = {k: value(rows, "streams", "generated", "640x480", what, k) for k in keys}
    s["fps"] = s["fps"] if s["frames_tracked"] is not None else None  # older runs: frames pushed
    return s


def streams_counts(s):
    return (f"{s['frames_tracked']:.0f} of {s['frames_pushed']:.0f} frames tracked, "
            f"{s['pushes_refused']:.0f} pushes refused, {s['timeouts']:.0f} streams timed out "
            f"after {s['timeout_s']:.0f} s, {s['errors']:.0f} errors")
