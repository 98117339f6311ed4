#!/usr/bin/python3
"""Writes docs/performance.md from projtrack-speed's measurements (./run bench --speed).

Usage: bench/speed/report.py DATA_DIR OUTPUT.md
Reads DATA_DIR/speed.csv, DATA_DIR/methods.csv (the table of methods) and DATA_DIR/meta.json;
draws DATA_DIR/figures/cost_by_object_size.svg.
Every number and verdict is computed here from the measurements or read from meta.json, never
written by hand; a target whose numbers are missing reads "not measured", never "met".
"""
import csv
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from report_kit import (DASH, MISSING, TARGET, fmt_pct, fmt_res, fmt_x,  # noqa: E402
                        frame_size, load_meta, load_methods, missing, plt, verdict)

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


def per_frame_table(rows, methods, clip, res, default):
    out = ["| contender | per frame (median) | × frame copy | Canny + floodFill ÷ it | MOSSE ÷ it |",
           "|---|---|---|---|---|"]
    for what in [COPY, HARNESS, ELEMENT] + [f"projtrack {m}" for m in methods] + [PEER_CV,
                                                                                PEER_MOSSE]:
        us = value(rows, "per_frame", clip, res, what, "median_us")
        if us is None:
            continue
        to_copy = value(rows, "ratio", clip, res, f"{what} / {COPY}", "median")
        cv_ratio = value(rows, "ratio", clip, res, f"{PEER_CV} / {what}", "median")
        mosse = value(rows, "ratio", clip, res, f"{PEER_MOSSE} / {what}", "median")
        name = f"**{what}**" if what == f"projtrack {default}" else what
        out.append(f"| {name} | {fmt_us(us)} | {fmt_x(to_copy, DASH)} | "
                   f"{fmt_x(cv_ratio, DASH)} | {fmt_x(mosse, DASH)} |")
    return "\n".join(out)


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


def size_figure(sizes, methods, resolutions, path):
    fig, axes = plt.subplots(1, max(1, len(resolutions)), figsize=(11, 4.2), sharey=True,
                             squeeze=False)
    for ax, res in zip(axes[0], resolutions):
        for m in methods:
            pts = sizes.get((res, m), [])
            if pts:
                ax.plot([p for p, _ in pts], [u / 1000 for _, u in pts], marker="o", label=m)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"{res}: {megapixels(res)} frame")
        ax.set_xlabel("object area (px)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("ms per frame (library, one thread)")
    axes[0][-1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


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


def targets(rows, meta, default, methods):
    """The six targets: [(number, target, measured, verdict)]."""
    d = f"projtrack {default}"
    # Targets 1 and 3: the element as users run it (the appearance model), and only it: without
    # its numbers they are not measured (the estimator alone is another job); target 2, the
    # estimator's own job on the edges, which is what Canny + floodFill does.
    t1 = value(rows, "ratio", "generated", "1920x1080", f"{ELEMENT} / {COPY}", "median")
    t2 = value(rows, "ratio", "generated", "1920x1080", f"{PEER_CV} / {d}", "median")
    t3 = value(rows, "ratio", "generated", "640x480", f"{PEER_MOSSE} / {ELEMENT}", "median")
    share = value(rows, "clip", "generated", "1920x1080", "object", "share_of_frame")
    out = [
        (1, f"the element with its defaults (the appearance model, {default}), 1920×1080 I420, "
            f"object {fmt_pct(share)} of the frame: ≤ {T1_COPIES}× a frame copy", fmt_x(t1),
         verdict([t1], t1 is not None and t1 <= T1_COPIES, words=TARGET)),
        (2, f"the estimator's own job ({default} on the edges, `object-model=edges`): "
            f"≥ {T2_CANNY_FLOOD}× faster than Canny over the frame + `cv::floodFill`, 1080p",
         fmt_x(t2), verdict([t2], t2 is not None and t2 >= T2_CANNY_FLOOD, words=TARGET)),
        (3, f"the element with its defaults ≥ {T3_MOSSE}× faster than `cvtracker` MOSSE (given RGB), "
            f"640×480",
         fmt_x(t3),
         verdict([t3], t3 is not None and t3 >= T3_MOSSE, words=TARGET)),
    ]

    growth, resolutions, pixel_ratio = growth_by_method(size_rows(rows), methods)
    worst = max((g for g, *_ in growth.values()), default=None)
    out.append((4, f"every method's cost grows with the object, not the frame (the same object "
                   f"in the larger frame: under {T4_GROWTH}× the cost)",
                MISSING if worst is None else
                f"the same object costs at most {worst:.2f}× as much in a frame with "
                f"{pixel_ratio:.2f}× the pixels (median over sizes)",
                verdict([worst], worst is not None and worst < T4_GROWTH, words=TARGET)))

    allocs = {r["what"]: r["value"] for r in rows if r["section"] == "allocations"}
    lib = [v for k, v in allocs.items() if k.startswith("Tracker::track")]
    lib_max = None if not lib or missing(*lib) else max(lib)
    el_on = allocs.get("projtrack element (messages on)")
    el_off = allocs.get("projtrack element (post-messages=false)")
    rss0 = value(rows, "memory", "generated", "1920x1080", "projtrack element", "rss_kib_at_mark")
    rss1 = value(rows, "memory", "generated", "1920x1080", "projtrack element", "rss_kib_at_end")
    mark = value(rows, "memory", "generated", "1920x1080", "projtrack element", "mark_frames")
    frames = value(rows, "memory", "generated", "1920x1080", "projtrack element", "frames")
    grew = None if missing(rss0, rss1, mark, frames) else rss1 - rss0
    out.append((5, "the library (`Tracker::track`, every method) allocates nothing per frame, "
                   f"and the element's resident memory grows by less than {T5_FLAT_KIB} KiB "
                   "over the long run. Not judged: the element's own per-frame allocations "
                   "(measured: see below)",
                f"library: {MISSING if lib_max is None else f'{lib_max:g}'} allocations per "
                f"frame (the most any method made); element resident memory "
                + (MISSING if grew is None else
                   f"{'+' if grew >= 0 else ''}{grew:.0f} KiB from frame {mark:.0f} to "
                   f"{frames:.0f}")
                + f"; the element allocates {MISSING if missing(el_on) else f'{el_on:g}'} per "
                f"frame, {MISSING if missing(el_off) else f'{el_off:g}'} with "
                "`post-messages=false`",
                verdict([lib_max, grew], lib_max == 0 and grew is not None and
                        grew < T5_FLAT_KIB, words=TARGET)))

    s = streams(rows, T6_STREAMS)
    need = T6_STREAMS * T6_FPS
    cores = value(rows, "streams", "generated", "640x480", "cores", "count")
    clean = s["timeouts"] == 0 and s["errors"] == 0
    out.append((6, f"{T6_STREAMS} concurrent 640×480 {T6_FPS} fps streams in one process, "
                   f"{MISSING if cores is None else f'{cores:.0f}'} cores",
                MISSING if s["fps"] is None else
                f"{s['fps']:.0f} frames tracked per second together, {s['fps'] / need:.1f}× the "
                f"{need} needed ({streams_counts(s)})",
                verdict([s["fps"], s["timeouts"], s["errors"]],
                        s["fps"] is not None and s["fps"] >= need and clean, words=TARGET)))
    return out


def adversarial_by_method(rows, methods):
    """Per method, the element with its defaults: (median µs of an ordinary frame, worst µs on the
    adversarial set, the content and start of that worst frame); None where not measured."""
    out = {}
    for m in methods:
        median = value(rows, "adversarial", "generated", BOUNDED_RES, m, "median_us")
        worst, where = None, None
        for r in rows:
            if (r["section"], r["resolution"], r["key"]) != ("adversarial", BOUNDED_RES,
                                                            "worst_us"):
                continue
            what = r["what"]
            if not what.startswith(m + " "):
                continue
            if missing(r["value"]):  # a frame not measured: no worst frame to judge
                worst, where = float("nan"), None
                break
            if worst is None or r["value"] > worst:
                worst, where = r["value"], f"{r['clip']}, {what[len(m) + 1:]}"
        out[m] = (median, worst, where)
    return out


def extreme_rows(rows):
    """Per setting: (worst µs over every clip, the clip, {status: frames})."""
    out = {}
    for r in rows:
        if r["section"] != "extreme" or r["resolution"] != BOUNDED_RES:
            continue
        worst, where, statuses = out.get(r["what"], (None, None, {}))
        if r["key"] == "worst_us":
            if missing(r["value"]):
                worst, where = float("nan"), r["clip"]  # a NaN never passes
            elif worst is None or (not missing(worst) and r["value"] > worst):
                worst, where = r["value"], r["clip"]
        elif r["key"].startswith("status_"):
            name = r["key"][len("status_"):]
            statuses[name] = statuses.get(name, 0) + r["value"]
        out[r["what"]] = (worst, where, statuses)
    return out


def interrupt_values(rows):
    what = "set_state(NULL) during a heavy frame"
    keys = ["latency_us_median", "latency_us_max", "trials", "frames_interrupted"]
    return {k: value(rows, "interrupt", "uniform", BOUNDED_RES, what, k) for k in keys}


def bounded_targets(rows, methods):
    """Targets 7–9 (issue 16): [(number, target, measured, verdict)]."""
    out = []
    per = adversarial_by_method(rows, methods)
    ratios = {m: per[m][1] / per[m][0] for m in methods
              if not missing(*per[m][:2]) and per[m][0] > 0}
    if not methods or len(ratios) < len(methods):
        measured, ok = MISSING, False
    else:
        rm = max(ratios, key=ratios.get)
        wm = max(methods, key=lambda m: per[m][1])
        measured = (f"worst ÷ ordinary median at most {ratios[rm]:.1f}× ({rm}: "
                    f"{fmt_us(per[rm][1])} on {per[rm][2]}, against {fmt_us(per[rm][0])}); "
                    f"the worst frame {fmt_us(per[wm][1])} ({wm}, {per[wm][2]})")
        ok = ratios[rm] <= T7_RATIO and per[wm][1] <= 1000 * T7_MS
    out.append((7, f"adversarial content at {fmt_res(BOUNDED_RES)}, the element's defaults with "
                   f"each method: the worst frame ≤ {T7_RATIO}× the median frame of the same "
                   f"method on ordinary content, and ≤ {T7_MS} ms",
                measured, verdict([None] if measured == MISSING else [], ok, words=TARGET)))

    ext = extreme_rows(rows)
    worsts = [(w, s, where) for s, (w, where, _) in ext.items()]
    if not ext or any(missing(w) for w, _, _ in worsts):
        measured, ok = MISSING, False
    else:
        w, setting, where = max(worsts, key=lambda t: t[0])
        measured = (f"the worst frame {fmt_us(w)} (`{setting}`, on {where}) over "
                    f"{len(ext)} settings")
        ok = w <= 1000 * T8_MS
    out.append((8, f"any valid settings (a sample at their extremes, the default `max-work`), "
                   f"{fmt_res(BOUNDED_RES)}: the worst frame ≤ {T8_MS} ms",
                measured, verdict([None] if measured == MISSING else [], ok, words=TARGET)))

    iv = interrupt_values(rows)
    if missing(*iv.values()) or not iv["trials"]:
        measured, ok = MISSING, False
    else:
        measured = (f"at most {fmt_us(iv['latency_us_max'])} (median "
                    f"{fmt_us(iv['latency_us_median'])}) over {iv['trials']:.0f} trials; "
                    f"{iv['frames_interrupted']:.0f} of them ended the frame `interrupted`")
        ok = (iv["latency_us_max"] <= 1000 * T9_MS and
              iv["frames_interrupted"] == iv["trials"])
    out.append((9, f"`set_state(NULL)` during a frame that would take minutes (no work limit) "
                   f"returns within {T9_MS} ms",
                measured, verdict([None] if measured == MISSING else [], ok, words=TARGET)))
    return out


def bounded_section(rows, methods, default):
    """The markdown of the bounded-work measurements (sections 7–9), or [] when none."""
    per = adversarial_by_method(rows, methods)
    ext = extreme_rows(rows)
    iv = interrupt_values(rows)
    if all(missing(*v[:2]) for v in per.values()) and not ext and missing(*iv.values()):
        return []
    contents = sorted({r["clip"] for r in rows if r["section"] == "adversarial"
                       and r["clip"] != "generated"})
    md = ["## Bounded work: adversarial content and extreme settings\n",
          "Every frame timed alone, at " + fmt_res(BOUNDED_RES) + ": each configuration runs its "
          "frames several times in one element (the track reset between runs), and a frame's "
          "time is the least of its runs: what it costs, without the shared machine's noise. "
          "The adversarial set (`synthetic/adversarial.hpp`: " + (", ".join(contents) or MISSING)
          + ") is fresh content on every frame, made to cost the estimators and the edges as "
          "much as it can. The tests (`tests/tracker/test_work_budget.cpp`, "
          "`tests/gst/test_element_budget.cpp`) assert the work each frame does against its "
          "budget, never a time; these are the times that work comes to.\n"]
    md.append("### The element's defaults, each method\n")
    md.append("From no point (`acquisition=auto`) and from a point at the frame's centre "
              "(seeded); ordinary content is the generated clip of the tables above (a sphere, "
              "found by its motion).\n")
    md.append("| method | ordinary frame (median) | adversarial: worst frame | on | worst ÷ "
              "ordinary |")
    md.append("|---|---|---|---|---|")
    for m in methods:
        median, worst, where = per[m]
        ratio = None if missing(median, worst) or not median else worst / median
        name = f"**{m}**" if m == default else m
        md.append(f"| {name} | {MISSING if missing(median) else fmt_us(median)} | "
                  f"{MISSING if missing(worst) else fmt_us(worst)} | {where or '–'} | "
                  f"{fmt_x(ratio, DASH)} |")
    md.append("")
    if ext:
        md.append("### Settings at their extremes\n")
        md.append("Each on the adversarial set and on the ordinary clip, with the default "
                  "`max-work`: the worst frame, and how the frames of the last run ended.\n")
        md.append("| settings | worst frame | on | frames by status |")
        md.append("|---|---|---|---|")
        for setting, (w, where, statuses) in ext.items():
            st = ", ".join(f"{k} {v:.0f}" for k, v in sorted(statuses.items()))
            md.append(f"| `{setting}` | {MISSING if missing(w) else fmt_us(w)} | "
                      f"{where or '–'} | {st or '–'} |")
        md.append("")
    if not missing(*iv.values()):
        md.append("### Stopping during a heavy frame\n")
        md.append("A pipeline `appsrc ! projtrack ! fakesink` whose element is in a frame that "
                  "would take minutes (`max-work=0`, a million rays per cast across a uniform "
                  "frame): `gst_element_set_state(NULL)` is called once the frame is well under "
                  f"way. Over {iv['trials']:.0f} trials it returned in "
                  f"{fmt_us(iv['latency_us_median'])} (median), {fmt_us(iv['latency_us_max'])} "
                  f"at most; {iv['frames_interrupted']:.0f} of the frames ended `interrupted`.\n")
    return md


def ordinary_work_section(rows):
    """The work ordinary frames need against the default budget, or [] when not measured."""
    clips = []
    for r in rows:
        if r["section"] == "ordinary_work" and (r["clip"], r["resolution"]) not in clips:
            clips.append((r["clip"], r["resolution"]))
    if not clips:
        return []
    budget = next((r["value"] for r in rows if r["section"] == "ordinary_work"
                   and r["what"] == "default max-work"), None)
    md = ["## Work per frame on ordinary content\n",
          "Not a time: the work (`TrackResult::work`, units of about one pixel of a fill: "
          "`include/projtrack/work_budget.hpp`) each frame needs with no limit, as a multiple of the frame's "
          "pixels, for the tracker with the element's defaults and each object model and "
          "method; then the same frames with the default budget of "
          + (MISSING if budget is None else f"{budget:g}") + " × the frame's pixels: the frames "
          "it cut short (`over-budget`) and those whose outcome (status, centroid, area) differs "
          "from the unlimited run's.\n"]
    for clip, res in clips:
        whats = []
        for r in rows:
            if (r["section"], r["clip"], r["resolution"]) == ("ordinary_work", clip, res) and \
                    r["what"] != "default max-work" and r["what"] not in whats:
                whats.append(r["what"])
        frames = value(rows, "ordinary_work", clip, res, whats[0], "frames") if whats else None
        title = ("the generated clip" if clip == "generated" else
                 "the real clip (Megamind.avi)" if clip == "real" else clip)
        md.append(f"### {title[0].upper() + title[1:]}, {fmt_res(res)}, "
                  f"{MISSING if frames is None else f'{frames:.0f}'} frames\n")
        md.append("| model, method | median | 99th percentile | most | frames over budget | "
                  "frames changed |")
        md.append("|---|---|---|---|---|---|")
        for w in whats:
            v = {k: value(rows, "ordinary_work", clip, res, w, k)
                 for k in ["median_x", "p99_x", "max_x", "over_budget_frames", "changed_frames"]}
            cell = lambda x, f: MISSING if x is None else f.format(x)  # noqa: E731
            md.append(f"| {w} | {cell(v['median_x'], '{:.2f}×')} | {cell(v['p99_x'], '{:.2f}×')} "
                      f"| {cell(v['max_x'], '{:.2f}×')} | {cell(v['over_budget_frames'], '{:.0f}')} "
                      f"| {cell(v['changed_frames'], '{:.0f}')} |")
        md.append("")
    return md


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


def main():
    data_dir, out_md = sys.argv[1], sys.argv[2]
    rows, meta = load(data_dir)
    methods = [m["method"] for m in load_methods(data_dir)]
    default = next((r["key"] for r in rows if r["section"] == "meta"
                    and r["what"] == "default method"), None)
    if default is None:
        sys.exit("bench/speed/report.py: speed.csv does not say the element's default method")
    os.makedirs(os.path.join(data_dir, "figures"), exist_ok=True)
    sizes = size_rows(rows)
    growth, resolutions, pixel_ratio = growth_by_method(sizes, methods)
    fig_path = os.path.join(data_dir, "figures", "cost_by_object_size.svg")
    size_figure(sizes, methods, resolutions, fig_path)
    rel = lambda p: os.path.relpath(p, os.path.dirname(os.path.abspath(out_md)))  # noqa: E731

    md = []
    md.append("# Performance\n")
    md.append("Generated by `./run bench --speed` (`build/bench/speed/projtrack-speed`, then "
              "`bench/speed/report.py`): do not edit by hand. Every number is a median over "
              "rounds in which all contenders ran back to back on the same decoded frames, "
              "and every ratio is the median of the per-round ratios, so a noisy, shared machine "
              "slows all of them alike. No test asserts a time.\n")
    md.append(f"Machine: {meta.get('cpu', '?')}, {meta.get('cores', '?')} cores; OpenCV "
              f"{meta.get('opencv', '?')} (one thread: `cv::setNumThreads(1)`, which cvtracker's "
              f"OpenCV shares), {meta.get('gstreamer', '?')}. Measured "
              f"{meta.get('measured', 'at a time not recorded')}.\n")

    md.append("## Targets\n")
    md.append("| # | target | measured | verdict |")
    md.append("|---|---|---|---|")
    for number, target, measured, result in (targets(rows, meta, default, methods) +
                                             bounded_targets(rows, methods)):
        md.append(f"| {number} | {target} | {measured} | {result} |")
    md.append("")

    canny = meta.get("canny")
    md.append("## Per-frame cost, every method\n")
    md.append("The element is measured in a `GstHarness` (push a buffer, pull it back) with its "
              "messages posted to a flushing bus; the harness's own cost is shown alone (an "
              "`identity` element) and is included in projtrack's numbers. The frame copy is a "
              "`memcpy` of the whole I420 frame from a buffer that is not in cache, as a decoded "
              "frame arrives. The stock-OpenCV peer is `cv::Canny` ("
              + (f"{canny[0]:g}/{canny[1]:g}" if canny else "thresholds not recorded")
              + ", no blur) over the whole frame and a 4-connected `cv::floodFill` from the true "
              "centroid with `cv::moments` for the centroid. `cvtracker` (gst-plugins-bad) runs "
              "MOSSE from the object's true box on the first frame, on RGB frames converted "
              "beforehand. `projtrack element default` is the element as users run it (the "
              "appearance model: the whole object's silhouette, the estimator on its outline); "
              "the `projtrack <method>` rows run each estimator on the edges alone "
              "(`object-model=edges`), the same job as the stock-OpenCV peer's.\n")
    for clip in ["generated", "real"]:
        for res in ["640x480", "1920x1080"]:
            if value(rows, "per_frame", clip, res, COPY, "median_us") is None:
                continue
            frames = value(rows, "clip", clip, res, "frames", "count")
            if clip == "generated":
                share = value(rows, "clip", clip, res, "object", "share_of_frame")
                title = (f"Generated: a shaded sphere covering {fmt_pct(share)} of the frame, "
                         "swinging across it, sensor noise on every frame")
            else:
                title = (f"Real clip: opencv-doc's Megamind.avi ({frames:.0f} frames, scaled), "
                         "projtrack with `acquisition=auto`")
            md.append(f"### {title} — {fmt_res(res)}\n")
            md.append(per_frame_table(rows, methods, clip, res, default))
            md.append("")
    start = value(rows, "clip", "real", "640x480", "start box", "share_of_frame")
    md.append("On the real clip nothing tells projtrack what to track: it spends many frames "
              "searching (motion detection and candidate fills on whole-frame edges) or "
              "lost, and those frames cost whole-frame edge detection. The fills stop as soon as "
              "an estimate passes what would be refused (`leak-factor` × the last area, or "
              "`max_area` of the frame), so a leak costs about the object's size, but acquisition "
              f"still looks at the whole frame. cvtracker's start box there is a centred box of "
              f"{fmt_pct(start)} of the frame, and the OpenCV peer fills from the frame "
              "centre.\n")

    statuses = [r for r in rows if r["section"] == "real_statuses"]
    if statuses:
        md.append("## What each method makes of the real clip\n")
        md.append("Not a time, and no ground truth: the tracker as the element runs it "
                  "(`acquisition=auto`, every default) over the real clip at "
                  f"{fmt_res(statuses[0]['resolution'])}, frame by frame. *Refused as a leak*: an "
                  "estimate whose area jumped past `leak-factor` × the last one or covered too "
                  "much of the frame; *lost otherwise*: one that shrank or fell under the "
                  "minimum; *acquisitions*: tracks started.\n")
        keys = ["tracked", "refused_as_leak", "lost_otherwise", "searching", "acquisitions"]
        md.append("| method | " + " | ".join(k.replace("_", " ") for k in keys) + " |")
        md.append("|---|" + "---|" * len(keys))
        for m in methods:
            vals = {r["key"]: r["value"] for r in statuses if r["what"] == m}
            if vals:
                name = f"**{m}**" if m == default else m
                md.append(f"| {name} | " + " | ".join(f"{vals.get(k, 0):.0f}" for k in keys) + " |")
        md.append("")

    md.append("## Cost against the object's size\n")
    md.append(f"![cost by object size]({rel(fig_path)})\n")
    if growth:
        small, large = resolutions[0], resolutions[-1]
        common = sorted({p for _, common, _, _ in growth.values() for p in common})
        hdr = " | ".join(f"{p} px" for p in common)
        md.append(f"| method | {fmt_res(small)}: {hdr} | {fmt_res(large)}: {hdr} | "
                  f"{fmt_res(large)} ÷ {fmt_res(small)} | largest ÷ smallest object, "
                  f"{fmt_res(large)} |")
        md.append("|---|" + "---|" * (2 * len(common) + 2))
        for m, (g, ps, a, b) in growth.items():
            md.append(f"| {m} | " + " | ".join(fmt_us(a.get(p)) for p in common) + " | "
                      + " | ".join(fmt_us(b.get(p)) for p in common)
                      + f" | {g:.2f}× | {b[ps[-1]] / b[ps[0]]:.1f}× |")
        md.append("")
        lo, hi = min(g for g, *_ in growth.values()), max(g for g, *_ in growth.values())
        md.append("The library alone (`Tracker::track` with edges computed by the tracker), one "
                  f"object in place with fresh noise on every frame. A frame with "
                  f"{pixel_ratio:.2f}× the pixels costs {lo:.2f}–{hi:.2f}× as much for the same "
                  "object (each method's median over sizes): edges are computed only around the "
                  "object, and every buffer (edge map, fill masks) is cleared only where it was "
                  "written.\n")

    edges = edge_cases(rows)
    regions = [c for c in edges if c[0] > 0]
    if edges:
        md.append("## Our Canny and box blur against OpenCV's\n")
        md.append("Side by side in one run, on the same crops of the same generated frames: the "
                  f"regions the tracker computes edges in around an object at rest with the "
                  f"default method ({default}; the object's box grown as \"What makes it fast\" says), "
                  "and whole frames (what searching costs). The box blur is one 3×3 pass "
                  "(`cv::blur` with replicated borders); Canny runs on the blurred crop with the "
                  "element's thresholds (`cv::Canny`, 3×3 Sobel, L1 gradient). Both give the same "
                  "edges, bit for bit (tested on random images and sizes).\n")
        md.append(f"| object | region | {BLUR} | {CV_BLUR} | {CV_BLUR} ÷ ours | {CANNY} | "
                  f"{CV_CANNY} | {CV_CANNY} ÷ ours |")
        md.append("|---|---|---|---|---|---|---|---|")
        for px, region, res, us, blur_ratio, canny_ratio in edges:
            obj = f"{px:.0f} px" if px > 0 else "whole frame"
            md.append(f"| {obj} | {fmt_res(region)} | {fmt_us(us[BLUR])} | "
                      f"{fmt_us(us[CV_BLUR])} | {fmt_x(blur_ratio, DASH)} | "
                      f"{fmt_us(us[CANNY])} | {fmt_us(us[CV_CANNY])} | "
                      f"{fmt_x(canny_ratio, DASH)} |")
        md.append("")

    allocs = {r["what"]: r["value"] for r in rows if r["section"] == "allocations"}
    counted = value(rows, "allocation_count", "generated", "1920x1080", "frames counted", "count")
    md.append("## Allocations and memory\n")
    md.append("Counted by interposing `malloc` and its relatives in `projtrack-speed` (GLib's "
              "slices included, `G_SLICE=always-malloc`), over "
              f"{MISSING if counted is None else f'{counted:.0f}'} frames after warm-up.\n")
    md.append("| what | heap allocations per frame |")
    md.append("|---|---|")
    for k, v in allocs.items():
        md.append(f"| {k} | {MISSING if missing(v) else f'{v:g}'} |")
    md.append("")
    lib = [v for k, v in allocs.items() if k.startswith("Tracker::track")]
    lib_max = None if not lib or missing(*lib) else max(lib)
    el_on = allocs.get("projtrack element (messages on)")
    el_off = allocs.get("projtrack element (post-messages=false)")
    if lib_max == 0:
        md.append("The library (`Tracker::track`, every method) made no allocation per frame: "
                  "its edge, blur, Canny and fill buffers are kept and grow only to the largest "
                  "region seen. So the element's "
                  + (MISSING if missing(el_on) else f"{el_on:g}")
                  + " per frame are all its glue's: the ROI meta and its `GstStructure` of "
                  "parameters (the buffer is made writable to carry them), and with messages on, "
                  "the message and its structure ("
                  + (MISSING if missing(el_off) else f"{el_off:g}")
                  + " with `post-messages=false`).\n")
    elif lib_max is not None:
        md.append(f"The library (`Tracker::track`) made up to {lib_max:g} allocations per frame "
                  "(the most any method made): target 5 is not met.\n")
    rss0 = value(rows, "memory", "generated", "1920x1080", "projtrack element", "rss_kib_at_mark")
    rss1 = value(rows, "memory", "generated", "1920x1080", "projtrack element", "rss_kib_at_end")
    mark = value(rows, "memory", "generated", "1920x1080", "projtrack element", "mark_frames")
    frames = value(rows, "memory", "generated", "1920x1080", "projtrack element", "frames")
    if not missing(rss0, rss1, mark, frames):
        grew = rss1 - rss0
        md.append("Resident memory of the whole benchmark process (the decoded clips it holds "
                  f"included) while the element runs: {rss0 / 1024:.1f} MiB after {mark:.0f} "
                  f"frames, {rss1 / 1024:.1f} MiB after {frames:.0f} (1080p). What matters is "
                  f"the difference, {'+' if grew >= 0 else ''}{grew:.0f} KiB over "
                  f"{frames - mark:.0f} frames: "
                  + (f"less than the {T5_FLAT_KIB} KiB target 5 allows.\n" if grew < T5_FLAT_KIB
                     else f"more than the {T5_FLAT_KIB} KiB target 5 allows.\n"))

    s8, s1 = streams(rows, T6_STREAMS), streams(rows, 1)
    cores = value(rows, "streams", "generated", "640x480", "cores", "count")
    if s8["fps"] is not None:
        md.append("## Concurrent streams\n")
        md.append(f"{T6_STREAMS} pipelines `appsrc ! projtrack ! fakesink sync=false` in one "
                  "process, each with its own streaming thread, fed 640×480 I420 frames as fast "
                  "as they take them. A frame counts when its projtrack message arrived with a "
                  "tracking status (one that carries features); every push's result and every "
                  "stream's end are checked. "
                  f"{s8['fps']:.0f} frames tracked per second together on "
                  f"{MISSING if cores is None else f'{cores:.0f}'} cores "
                  f"({s8['fps'] / T6_STREAMS:.0f} per stream; {T6_FPS} needed): "
                  f"{streams_counts(s8)}. One stream alone: "
                  + (MISSING if s1["fps"] is None else
                     f"{s1['fps']:.0f} frames tracked per second ({streams_counts(s1)})") + ".\n")

    md.extend(bounded_section(rows, methods, default))
    md.extend(ordinary_work_section(rows))

    margin, least = meta.get("edge_margin"), meta.get("least_margin_px")
    md.append("## What makes it fast\n")
    md.append("- **Edges only around the object.** While tracking, edges are computed in the last "
              "box and that box moved by the object's last motion, grown by "
              + (f"{100 * margin:g} % of its larger side (at least {least:g} px)"
                 if margin is not None and least is not None else "a margin (not recorded)")
              + ", and for gap-tolerant filling by the band it reads beside its lines. An estimate that reaches the region's border (anything it read: its box and "
              "every ray's end) is redone on a wider region, then on the whole frame, so the "
              "answer never depends on the region (tested for every method against whole-frame "
              "edges).\n"
              "- **Our own Canny and box blur** (`src/edges/canny.cpp`, `src/edges/box_blur.cpp`): the same "
              "edges as `cv::Canny` and `cv::blur`, bit for bit, on buffers kept between calls. "
              "Measured above on the regions the tracker asks for, ours are "
              f"{speed_phrase([c[4] for c in regions])} (box blur) and "
              f"{speed_phrase([c[5] for c in regions])} (Canny); on whole frames, "
              f"{speed_phrase([c[4] for c in edges if c[0] == 0])} (box blur) and "
              f"{speed_phrase([c[5] for c in edges if c[0] == 0])} (Canny).\n"
              "- **Leaks stop early.** The fills stop once the area passes what the tracker would "
              "refuse, so a leak through a gap costs about the object's size, not the frame's.\n"
              "- **A search reads the frame a fixed number of times.** While no object is "
              "tracked, the finder reads the whole frame at a coarse scale, and counts motion "
              "only around the regions that pass its size, border and background tests, per "
              "coarse pixel rather than per changed sample: a frame where everything moves "
              "(noise, a checkerboard that inverts) is the adversarial set's worst frame above.\n"
              "- **Nothing is cleared or allocated per frame beyond what was touched**: masks are "
              "cleared only in the box the fill wrote.\n")

    md.append("## Reproduce\n")
    md.append("```\n./run bench --speed          # a few minutes; writes docs/performance.md\n"
              "./run bench --speed --quick  # a smoke run into build/speed-quick/\n```\n")
    md.append("Needs `gstreamer1.0-opencv` (cvtracker) and `opencv-doc` (the clip); "
              "`./run bench --speed` installs them. Raw numbers: "
              f"[{rel(os.path.join(data_dir, 'speed.csv'))}]"
              f"({rel(os.path.join(data_dir, 'speed.csv'))}), "
              f"[{rel(os.path.join(data_dir, 'meta.json'))}]"
              f"({rel(os.path.join(data_dir, 'meta.json'))}).\n")
    with open(out_md, "w") as f:
        f.write("\n".join(md))


if __name__ == "__main__":
    main()
