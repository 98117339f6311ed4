#!/usr/bin/python3
"""The several-objects benchmark's report: from run.py's data, docs/multi.md (mosaics: together
against alone and identity; crossings: the front object's J, the hidden one occluded and found
again; cost against CSRT and the frame's budget) and its contact sheet. Every number is computed
from the run's data; what the run did not measure reads "not measured" and fails its target.

    report.py DATA_DIR DOC_DIR OUTPUT.md
"""
import argparse
import collections
import gzip
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from report_kit import DASH, MISSING, TARGET, fmt_num, fmt_pct, fmt_res, missing  # noqa: E402

import sheet  # noqa: E402
import tally as T  # noqa: E402

STARTS = [("mask", "first mask"), ("box", "box")]
J_TOLERANCE = 1.0      # points of J: together within this of alone
IDENTITY = 0.90        # share of frames each id lies on its own object
OCCLUDED_SHARE = 0.5   # the hidden object reported occluded on more than this share of its hidden frames
ON_FRONT = 0.10        # the hidden object's silhouette: at most this share on the front object
COST_4, COST_8, OF_CSRT = 2.0, 3.0, 0.10
FOLLOWED = 0.90      # a count's time counts when its objects were followed on this share of results


def fj(x):
    """J (0-1) as DAVIS writes it: 0-100, one decimal."""
    return fmt_num(None if missing(x) else 100 * x, 1)


def fd(x):
    """A difference of J, in points, signed."""
    return MISSING if missing(x) else f"{100 * x:+.1f}"


def target(values, ok):
    """met only when every value was measured and ok(*values) holds; a value not measured is a
    miss, never a pass."""
    if not values or missing(*values):
        return TARGET.fails
    return TARGET.holds if ok(*values) else TARGET.fails


def tile_name(scene, k):
    tiles = scene.get("tiles")
    if not tiles or not tiles[k]:
        return scene["objects"][k]
    x, y, _, _ = tiles[k]
    where = ("top" if y == 0 else "bottom") + " " + ("left" if x == 0 else "right")
    return f"{scene['objects'][k]} ({where})"


# ---- the introduction -----------------------------------------------------------------------------

def intro(run):
    m = run.meta
    mos, cro = run.of_kind("mosaic"), run.of_kind("crossing")
    quick = " (a quick run: a smoke test, not the benchmark)" if m["quick"] else ""
    frames = sum(s["frames"] for s in mos)
    limit = (f"at most {m['mosaic_frame_limit']} frames a mosaic" if m.get("mosaic_frame_limit")
             else "each over the whole of its shortest sequence (no frame left out)")
    load = " at the start, ".join(str(x) for x in m["machine"]["load"]) + " at the end"
    cost = m.get("cost", {})
    sizes = sorted({fmt_res(s["size"]) for s in mos})
    return f"""# Several objects at once: projtrack's MultiTracker on DAVIS composites

Written by `./run bench --multi` (bench/multi/report.py) from the run of {m['date']}{quick}: every
number below is computed from that run's data; "{MISSING}" marks what it did not measure, and a
target resting on it is not met.

**What it measures.** Whether following several objects at once in one `projtrack.MultiTracker`
(one frame's evidence and work budget shared, overlapping silhouettes given to the object in front,
the hidden one reported `occluded`: [tracker.md](tracker.md#several-objects-multitracker)) follows
each as well as following it alone, keeps each id on its own object, handles one object passing in
front of another, and what it costs beside as many OpenCV CSRT trackers. The scenes are composed
from `{os.path.basename(m['data'])}/` (DAVIS 2016, ten sequences with a true mask on every frame;
bench/multi/compose.py):

- **Mosaics**: {plural(len(mos), 'mosaic')} of 2×2 sequences ({', '.join(sizes) or MISSING} px),
  each sequence at half size in its quarter with its true masks resized alike; the sequences are
  cycled in name order, four to a mosaic, so that each of the {len({o for s in mos for o in
  s['objects']})} in them appears {_appearances(mos)}; {limit} ({frames} frames in all).
- **Crossings**: {plural(len(cro), 'composite')} in which one sequence's object, cut out of its frames by its
  true mask (and scaled so that it is 1.2× as high as the other object or as wide, within
  0.3–1.25×), is pasted onto another sequence's frames and swept sideways across that sequence's
  object — clear of it on frame 0, over it, out the other side some frames before the end — with
  its vertical place following the other object's smoothed centroid. The front object's truth is
  its pasted mask; the back object's is what of it still shows (its **visible share**: that over
  its whole mask).

Every object is started on frame 0 **from its first true mask** and, in a second run, **from its
box** (the first mask's tight bounding box), and followed **together** (one MultiTracker with every
object of the scene: `add(frame, mask=…)` or `add(frame, box=…)` each, then frame 0 tracked, as
`Tracker.init` starts on its frame) and **alone** (`projtrack.Tracker` with that object only,
`init(frame, mask)` or `init(frame, box)`, on the same frames; a MultiTracker with one object
follows it the same way: tracker.md). OpenCV's **CSRT** from the box runs beside, one per object
(OpenCV {m['opencv']}). Frames 1 .. N-2 of every scene are scored (the DAVIS 2016 protocol).

- **J**: the intersection over union of an object's reported silhouette (`Result.mask`; CSRT's box,
  filled) and its true mask (in a crossing, what of it shows), averaged over its frames, then over
  objects.
- **identity kept**: the share of frames on which an id's reported silhouette lies on its own
  object — it overlaps its own true mask, and more of it than of any other object's.
- **occluded**, **on the front object**, **found again**: in the crossings, below.
- **ms**: time.perf_counter around the call on each frame (`track()`, CSRT's `update()`), measured
  in this run on {m['machine']['cores']} cores ({m['machine']['cpu']}), shared with other work
  (load average {load}; OpenCV's threads: {m.get('opencv_threads', MISSING)}): read the times as
  this run's, side by side, not as the trackers' cost on an idle machine.

**How to run.** `./run bench --multi [DIR]` (DIR in DAVIS layout, default `../shared/davis-dev`
beside the repository) regenerates this page and `docs/multi/` (the contact sheet, the run's
`runs.csv`, `cost.csv`, `meta.json` and `frames.csv.gz`); `./run bench --multi --quick` is a smoke
run (one mosaic of 8 frames, one crossing of 16, the cost run on 6) into the build folder, docs
untouched. The whole run took {m['seconds']:.0f} s (the cost run {fmt_num(cost.get('seconds'), 0)} s
of it).
"""


def plural(n, word):
    return f"{n} {word}" + ("" if n == 1 else "s")


def _appearances(mosaics):
    counts = {}
    for s in mosaics:
        for o in s["objects"]:
            counts[o] = counts.get(o, 0) + 1
    lo, hi = min(counts.values(), default=0), max(counts.values(), default=0)
    times = {1: "once", 2: "twice"}
    word = times.get(lo, f"{lo} times")
    return word if lo == hi else f"{word} to {times.get(hi, f'{hi} times')}"


# ---- mosaics --------------------------------------------------------------------------------------

def mosaic_section(run):
    mos = run.of_kind("mosaic")
    objs = [(s, k) for s in mos for k in range(len(s["objects"]))]
    lines = ["## Mosaics: together against alone", "",
             "J per object (0–100) followed together (one MultiTracker, the mosaic's four objects, "
             "default settings) and alone (a Tracker, that object only), from its first mask and "
             "from its box; Δ: together less alone, in points; *together, no budget*: the same "
             "MultiTracker with `max_work=0` (no work budget: what following them together does "
             "without the shared budget; not a target's number); CSRT from the box beside:", ""]
    head = ["mosaic", "object (quarter)", "mask: together", "mask: alone", "mask: Δ",
            "mask: together, no budget", "box: together", "box: alone", "box: Δ",
            "box: together, no budget", "CSRT"]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    sums = {}
    for n, (s, k) in enumerate(objs):
        cells = []
        for start, _ in STARTS:
            tj = run.mean_of(s["name"], "together", start, k, "j")
            aj = run.mean_of(s["name"], "alone", start, k, "j")
            uj = run.mean_of(s["name"], "unlimited", start, k, "j")
            cells += [fj(tj), fj(aj), fd(tj - aj), fj(uj)]
            sums.setdefault(("together", start), []).append(tj)
            sums.setdefault(("alone", start), []).append(aj)
            sums.setdefault(("unlimited", start), []).append(uj)
        cj = run.mean_of(s["name"], "CSRT", "box", k, "j")
        sums.setdefault(("CSRT", "box"), []).append(cj)
        number = mos.index(s) + 1
        lines.append(f"| {number} | {tile_name(s, k)} | " + " | ".join(cells + [fj(cj)]) + " |")
    means = {key: T.pooled(v) for key, v in sums.items()}
    cells = []
    for start, _ in STARTS:
        t, a = means.get(("together", start), math.nan), means.get(("alone", start), math.nan)
        cells += [fj(t), fj(a), fd(t - a), fj(means.get(("unlimited", start), math.nan))]
    cells.append(fj(means.get(("CSRT", "box"), math.nan)))
    lines.append("| **mean** | | " + " | ".join(f"**{c}**" for c in cells) + " |")
    lines += _not_measured(run, "mosaic")
    # identity
    lines += ["", "Identity kept (the share of scored frames on which the id's silhouette lies on "
              "its own object) and the statuses (their shares of the frames) of the together runs "
              "and of the alone run from the mask, per object:", ""]
    head = ["mosaic", "object (quarter)", "mask: identity", "box: identity", "CSRT: identity",
            "mask: statuses together", "box: statuses together", "mask: statuses alone"]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    ids = {start: [] for start, _ in STARTS}
    frames = {start: [] for start, _ in STARTS}
    for s, k in objs:
        cells = []
        for start, _ in STARTS:
            v = run.values(s["name"], "together", start, k, "identity")
            share = T.mean(v.values()) if v else math.nan
            ids[start].append(share)
            frames[start] += list(v.values()) if v else [math.nan]
            cells.append(fmt_pct(share))
        c = run.values(s["name"], "CSRT", "box", k, "identity")
        cells.append(fmt_pct(T.mean(c.values()) if c else math.nan))
        for start, _ in STARTS:
            cells.append(statuses(run.values(s["name"], "together", start, k, "status")))
        cells.append(statuses(run.values(s["name"], "alone", "mask", k, "status")))
        lines.append(f"| {mos.index(s) + 1} | {tile_name(s, k)} | " + " | ".join(cells) + " |")
    # targets
    lines += ["", "| target | measured | verdict |", "|---|---|---|"]
    for start, words in STARTS:
        t, a = means.get(("together", start), math.nan), means.get(("alone", start), math.nan)
        lines.append(f"| from the {words}: J together within {J_TOLERANCE:g} point of alone "
                     f"(the mean over the {len(objs)} objects) | together {fj(t)}, alone {fj(a)} "
                     f"(Δ {fd(t - a)}) | "
                     f"{target([t, a], lambda t, a: 100 * (a - t) <= J_TOLERANCE)} |")
    for start, words in STARTS:
        pooled = T.pooled(frames[start])
        worst = min(ids[start]) if ids[start] and not missing(*ids[start]) else math.nan
        lines.append(f"| from the {words}: identity kept on ≥ {fmt_pct(IDENTITY)} of the frames "
                     f"(every id's frames pooled) | {fmt_pct(pooled, 1)} (the lowest id "
                     f"{fmt_pct(worst)}) | {target([pooled], lambda p: p >= IDENTITY)} |")
    return lines + [""]


def counted(counter):
    """'ok 60 %, over-budget 40 %' of a Counter of statuses."""
    total = sum(counter.values())
    if not total:
        return MISSING
    return ", ".join(f"{s} {fmt_pct(c / total)}" for s, c in
                     sorted(counter.items(), key=lambda x: (-x[1], x[0])))


def statuses(v):
    """'ok 96 %, occluded 4 %': the statuses' shares of a run's frames, most first."""
    return counted(collections.Counter(v.values())) if v else MISSING


def _not_measured(run, kind):
    """Why runs were not measured, and the runs whose tracker raised (their frames from there on
    are misses, status `error`)."""
    scenes = [s["name"] for s in run.of_kind(kind)]
    notes, raised = [], []
    for (sc, r, st, _), row in run.runs.items():
        if sc not in scenes or not row["note"]:
            continue
        if row["measured"] != "1":
            notes.append(f"{r} from the {st}: {row['note']}")
        else:
            raised.append(f"{sc}, {r} from the {st}: {row['note']}")
    out = []
    if notes:
        out += ["", "Not measured: " + "; ".join(dict.fromkeys(notes)) + "."]
    if raised:
        out += ["", "The tracker raised, its frames from there on misses (status `error`): "
                + "; ".join(dict.fromkeys(raised)) + "."]
    return out


# ---- crossings ------------------------------------------------------------------------------------

def crossing_section(run):
    cro = run.of_kind("crossing")
    lines = ["## Crossings: one object in front of another", "",
             "Per composite: the front object's scale and the least share of the back object that "
             "shows; then per start, the front object's J together (one MultiTracker, both "
             "objects; and with no work budget, `max_work=0`, not a target's number) and alone (a "
             "Tracker, it only); and what the together run did with the "
             "back object: on how many of its **hidden** frames (less than half of it shows) it "
             "was reported `occluded`; the share of its silhouette that lay **on the front "
             "object** on the frames where the two overlap and it was reported measured (`ok`, "
             "`reached-border`: pixels it claims; mean, and the most); the frame from which more "
             "than half of it shows again (**out**), and the first frame from there on which it is "
             "reported measured and **kept** (DAVIS's kept: its centroid within ¼·√area of the "
             "true centroid of what shows, its area within 0.5–2× that; **found**, and how many "
             "frames after coming out).", ""]
    head = ["front over back", "start", "run", "front scale", "least visible", "front J",
            "front J: alone", "Δ", "hidden frames", "occluded on them", "on the front (mean, most)",
            "out", "found (frames after)"]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    per = {start: [] for start, _ in STARTS}
    for s in cro:
        vis = [v for v in s["visible"][1:s["frames"] - 1]]
        for start, name in [(st, r) for st, _ in STARTS for r in ("together", "unlimited")]:
            tj = run.mean_of(s["name"], name, start, 0, "j")
            aj = run.mean_of(s["name"], "alone", start, 0, "j")
            c = T.crossing_numbers(run, s["name"], start, name)
            if name == "together":
                per[start].append((tj, aj, c))
            found = (MISSING if not c["measured"] else "never" if c["out"] is not None and
                     c["refound"] is None else DASH if c["out"] is None else
                     f"{c['refound']} ({c['delay']:.0f})")
            label = "together" if name == "together" else "together, no budget"
            lines.append(
                f"| {s['name']} | {start} | {label} | {s['scale']:.2f} | "
                f"{fmt_pct(min(vis) if vis else None)} "
                f"| {fj(tj)} | {fj(aj)} | {fd(tj - aj)} | {len(c['hidden'])} | "
                f"{fmt_pct(c['occluded'])} | {fmt_pct(c['on_front'])}, "
                f"{fmt_pct(c['on_front_max'])} | {c['out'] if c['out'] is not None else DASH} | "
                f"{found} |")
    lines += _not_measured(run, "crossing")
    lines += ["", "What the back object was reported while hidden and once out (the statuses' "
              "shares of those frames):", "",
              "| front over back | start | run | on its hidden frames | from coming out to N-2 |",
              "|---|---|---|---|---|"]
    for s in cro:
        for start, name in [(st, r) for st, _ in STARTS for r in ("together", "unlimited")]:
            status = run.values(s["name"], name, start, 1, "status")
            c = T.crossing_numbers(run, s["name"], start, name)
            hidden = {i: status[i] for i in c["hidden"] if i in status}
            after = {i: v for i, v in status.items() if c["out"] is not None and i >= c["out"]}
            label = "together" if name == "together" else "together, no budget"
            lines.append(f"| {s['name']} | {start} | {label} | "
                         f"{(statuses(hidden) if hidden else DASH) if status else MISSING} | "
                         f"{(statuses(after) if after else DASH) if status else MISSING} |")
    lines += ["", "| target | measured | verdict |", "|---|---|---|"]
    for start, words in STARTS:
        rows = per[start]
        t = T.pooled(r[0] for r in rows)
        a = T.pooled(r[1] for r in rows)
        lines.append(f"| from the {words}: the front object keeps its J, together within "
                     f"{J_TOLERANCE:g} point of alone (the mean over the {len(rows)} crossings) | "
                     f"together {fj(t)}, alone {fj(a)} (Δ {fd(t - a)}) | "
                     f"{target([t, a], lambda t, a: 100 * (a - t) <= J_TOLERANCE)} |")
    # the back object's targets: (what, its number per crossing, how it reads, when it holds)
    back = [(f"reported `occluded` on more than {fmt_pct(OCCLUDED_SHARE)} of its hidden frames",
             "occluded", fmt_pct, lambda x: x > OCCLUDED_SHARE),
            (f"not given the front one's pixels: at most {fmt_pct(ON_FRONT)} of its silhouette on "
             "the front object (mean over the frames it claims while they overlap)", "on_front",
             lambda v: fmt_pct(v, 1), lambda x: x <= ON_FRONT),
            (f"found again within {T.REFOUND_WITHIN} frames of coming out (never found, or never "
             "hidden: a miss)", "delay", lambda v: fmt_num(v, 0, " frames", "not found"),
             lambda x: x <= T.REFOUND_WITHIN)]
    for what, field, fmt, holds in back:
        for start, words in STARTS:
            vals = [r[2][field] for r in per[start]]
            lines.append(f"| from the {words}: the hidden object {what}, on every crossing | "
                         f"{', '.join(fmt(v) for v in vals) or MISSING} | "
                         f"{target(vals, lambda *v: all(holds(x) for x in v))} |")
    return lines + [""]


# ---- cost -----------------------------------------------------------------------------------------

def cost_section(run):
    c = T.cost_numbers(run)
    info = run.meta.get("cost", {})
    counts = sorted(c)

    def get(k, f):
        return c.get(k, {}).get(f, math.nan)

    def ratio(a, b):
        return a / b if not missing(a, b) and b else math.nan
    lines = ["## Cost: 1, 2, 4 and 8 objects against as many CSRTs", "",
             f"On one 4×2 mosaic of eight sequences, each at half size "
             f"({fmt_res(info.get('size', '?'))} px; {info.get('scene', MISSING).replace('+', ', ')}; "
             f"{info.get('frames', MISSING)} frames, frames 1 .. N-1 timed), a MultiTracker "
             "following the first 1, 2, 4 and 8 of its objects (from their first masks; with the "
             "default settings, and one with no work budget, `max_work=0`) and as many CSRTs "
             "(from their boxes), all on the same frames, side by side: on each frame each "
             "count's MultiTracker calls are timed, then its CSRTs' calls, summed. ms per frame "
             "(mean and median over the frames); **followed**: the share of the MultiTracker's "
             "results (one per object and frame) that measured their object (`ok`, "
             "`reached-border`) — a time is that of following the objects only where they were "
             "followed:", ""]
    head = ["objects", "projtrack ms (mean)", "median", "× one object", "followed",
            "no budget: ms (mean)", "× one object", "followed", "CSRTs ms (mean)", "median",
            "projtrack / CSRTs", "no budget / CSRTs"]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for k in counts:
        cells = [fmt_num(get(k, "ms"), 1), fmt_num(get(k, "ms_median"), 1),
                 fmt_num(ratio(get(k, "ms"), get(1, "ms")), 2), fmt_pct(get(k, "followed")),
                 fmt_num(get(k, "unlimited_ms"), 1),
                 fmt_num(ratio(get(k, "unlimited_ms"), get(1, "unlimited_ms")), 2),
                 fmt_pct(get(k, "unlimited_followed")), fmt_num(get(k, "csrt_ms"), 1),
                 fmt_num(get(k, "csrt_median"), 1),
                 fmt_num(ratio(get(k, "ms"), get(k, "csrt_ms")), 3),
                 fmt_num(ratio(get(k, "unlimited_ms"), get(k, "csrt_ms")), 3)]
        lines.append(f"| {k} | " + " | ".join(cells) + " |")
    if info.get("projtrack_note"):
        lines += ["", f"projtrack not measured: {info['projtrack_note']}."]
    if info.get("errors"):
        lines += ["", "The MultiTracker raised, and was called no more (its objects not followed "
                  "from there on): " + "; ".join(info["errors"]) + "."]
    lines += ["", "The statuses of the default MultiTracker's results: " + "; ".join(
        f"{k} object{'s' if k > 1 else ''}: {counted(get(k, 'statuses') or {})}" for k in counts)
        + ".", ""]
    lines += ["The targets are the default settings' (the MultiTracker as it ships), and a time "
              f"counts only where the objects were followed: on at least {fmt_pct(FOLLOWED)} of "
              "the results at each count the target compares (else not met).", "",
              "| target | measured | verdict |", "|---|---|---|"]
    for what, k, base, limit in ((f"4 objects ≤ {COST_4:g}× one", 4, 1, COST_4),
                                 (f"8 objects ≤ {COST_8:g}× one", 8, 1, COST_8),
                                 (f"4 objects ≤ {OF_CSRT:g} of four CSRTs", 4, None, OF_CSRT)):
        r = ratio(get(k, "ms"), get(base, "ms") if base else get(k, "csrt_ms"))
        followed = [get(k, "followed")] + ([get(base, "followed")] if base else [])
        words = f"followed {fmt_pct(followed[0])} ({k})" + (
            f", {fmt_pct(followed[1])} (one)" if base else "")
        lines.append(f"| {what} (mean ms per frame), the objects followed | "
                     f"{fmt_num(r, 3 if not base else 2)}{'×' if base else ''}; {words} | "
                     f"{target([r] + followed, lambda r, *f: r <= limit and min(f) >= FOLLOWED)} |")
    lines.append("")
    # the frame's work with the most objects
    most = max(counts) if counts else None
    limit = info.get("frame_limit")
    tl = info.get("tracker_work_limit")
    lines += [f"**The frame's work with {most or MISSING} objects.** Each object's "
              "`Result.work` (what its estimates did on the frame, in work units) summed over the "
              "objects, against the frame's budget: `max_work` "
              f"({fmt_num(info.get('max_work'), 0)}) × the frame's pixels, at least 1.5 MP's "
              "(`frame_work_limit()`, include/projtrack/tracker_params.hpp) = "
              f"{fmt_num(limit, 0)} units (a Tracker alone on these frames reports "
              f"`work_limit` {fmt_num(tl, 0)}). Each object's own `work_limit` is its share of "
              "what the objects before it left (cost.csv, work_limits). The MultiTracker with no "
              "budget shows the work following them all took:", "",
              "| MultiTracker | frames | the frame's work / its budget: mean | median | most | "
              "frames over the budget | results `over-budget` | followed |",
              "|---|---|---|---|---|---|---|---|"]
    most_share = math.nan
    for prefix, name in (("", "default settings"), ("unlimited_", "no budget")):
        work = get(most, prefix + "work") if most else []
        shares = [w / limit for w in work] if isinstance(work, list) and work and limit else []
        statuses = get(most, prefix + "statuses") if most else {}
        if prefix == "" and shares and len(shares) == get(most, "frames"):
            most_share = max(shares)  # the target rests on every timed frame's work
        lines.append(
            f"| {name} | {len(shares) if shares else MISSING} | "
            f"{fmt_pct(T.mean(shares) if shares else math.nan, 1)} | "
            f"{fmt_pct(T.median(shares) if shares else math.nan, 1)} | "
            f"{fmt_pct(max(shares) if shares else math.nan, 1)} | "
            f"{sum(1 for x in shares if x > 1) if shares else MISSING} | "
            f"{statuses.get('over-budget', 0) if shares else MISSING} | "
            f"{fmt_pct(get(most, prefix + 'followed') if most else math.nan)} |")
    lines += ["", "| target | measured | verdict |", "|---|---|---|",
              f"| with {most or MISSING} objects the frame's work within its budget on every "
              f"frame (the MultiTracker's bound: the objects share one frame's; a frame whose work "
              f"is missing, a miss) | the most {fmt_pct(most_share, 1)} | "
              f"{target([most_share], lambda m: m <= 1)} |", ""]
    return lines


# ---- the page -------------------------------------------------------------------------------------

def sheet_section(run, doc_dir, path):
    mosaics = run.of_kind("mosaic")

    def caption(s, i):
        if s["kind"] == "mosaic":
            return f"mosaic {mosaics.index(s) + 1}, frame {i}"
        return f"{s['name']}, frame {i}: {fmt_pct(s['visible'][i])} of 2 shows"
    rows = [sheet.scene_row(run.dir, s, lambda i, s=s: caption(s, i), 4)
            for s in mosaics + run.of_kind("crossing")]
    rows = [r for r in rows if r is not None]
    rel = os.path.relpath(doc_dir, os.path.dirname(os.path.abspath(path)))
    lines = ["## Contact sheet", ""]
    if not rows:
        return lines + [f"No frames kept: {MISSING}.", ""]
    sheet.write(rows, os.path.join(doc_dir, "contact_sheet.png"))
    objects = ", ".join(f"{k + 1} {name}" for k, name in
                        enumerate(sheet.COLOUR_NAMES))
    return lines + [
        "The together runs from the first masks: a row per mosaic (frames 1, N/3, 2N/3 and N-2) "
        "and per crossing (frame 1, the frame where the back object shows least, the first frame "
        "from which more than half of it shows again, and N-2). Each object's reported silhouette "
        "is outlined in its own colour with its id at its centroid (ids in the order added: "
        f"{objects}; in a crossing 1 is the front object, 2 the back one); the true masks (what "
        "shows) in thin white. A crossing's caption gives the share of the back object (2) that "
        "shows. An object with no silhouette on the frame (`Result.mask` None) has no outline.",
        "", f"![The together runs' silhouettes on mosaic and crossing frames]({rel}/contact_sheet.png)",
        ""]


def run_section(run):
    m = run.meta
    s = m["module"]["settings"]
    return ["## The run", "",
            f"- data: `{m['data']}`",
            "- mosaics: " + "; ".join(f"{n + 1}: {', '.join(x['objects'])} ({x['frames']} frames)"
                                      for n, x in enumerate(run.of_kind("mosaic"))),
            "- crossings: " + "; ".join(f"{x['name']} ({x['frames']} frames)"
                                        for x in run.of_kind("crossing")),
            f"- the repository's commit: {m.get('commit') or MISSING}",
            f"- projtrack module {m['module']['version']} "
            f"(`{os.path.basename(m['module']['file'])}`, MultiTracker: "
            f"{'yes' if m['module'].get('multi_tracker') else 'no'}), default settings: "
            + ", ".join(f"{k}={v}" for k, v in s.items()),
            f"- OpenCV {m['opencv']}, Python {m['python']}; {m['machine']['system']}, "
            f"{m['machine']['cores']} cores",
            f"- the whole run (composing, tracking, scoring, the cost run): {m['seconds']:.0f} s", ""]


def write_doc(run, doc_dir, path):
    lines = [intro(run)]
    lines += mosaic_section(run)
    lines += crossing_section(run)
    lines += cost_section(run)
    lines += sheet_section(run, doc_dir, path)
    lines += run_section(run)
    with open(path, "w") as f:
        f.write("\n".join(lines).rstrip() + "\n")


def main():
    ap = argparse.ArgumentParser()
    for a in ("data_dir", "doc_dir", "output"):
        ap.add_argument(a)
    a = ap.parse_args()
    run = T.Run(a.data_dir)
    os.makedirs(a.doc_dir, exist_ok=True)
    write_doc(run, a.doc_dir, a.output)
    if os.path.abspath(a.doc_dir) != os.path.abspath(a.data_dir):
        for name in ("runs.csv", "meta.json", "cost.csv"):
            shutil.copy(os.path.join(a.data_dir, name), os.path.join(a.doc_dir, name))
        with open(os.path.join(a.data_dir, "frames.csv"), "rb") as src, \
                gzip.GzipFile(os.path.join(a.doc_dir, "frames.csv.gz"), "wb", mtime=0) as dst:
            shutil.copyfileobj(src, dst)


if __name__ == "__main__":
    main()
