"""The targets' rows of docs/performance.md (bench/speed/report.py): each target's measurement
and verdict, from speed.csv's rows."""
from report_kit import MISSING, TARGET, fmt_pct, fmt_res, fmt_x, missing, verdict
from speed_data import (BOUNDED_RES, COPY, ELEMENT, PEER_CV, PEER_MOSSE, T1_COPIES,
                        T2_CANNY_FLOOD, T3_MOSSE, T4_GROWTH, T5_FLAT_KIB, T6_FPS, T6_STREAMS,
                        T7_MS, T7_RATIO, T8_MS, T9_MS, fmt_us, growth_by_method, size_rows,
                        streams, streams_counts, value)


def targets(rows, meta, default, methods):
    """The six targets: [(number, target, measured, verdict)]."""
    d = f"projtrack {default}"
    # Targets 1 and 3: the element as users run it (the default flow model), and only it: without
    # its numbers they are not measured (the estimator alone is another job); target 2, the
    # estimator's own job on the edges, which is what Canny + floodFill does.
    t1 = value(rows, "ratio", "generated", "1920x1080", f"{ELEMENT} / {COPY}", "median")
    t2 = value(rows, "ratio", "generated", "1920x1080", f"{PEER_CV} / {d}", "median")
    t3 = value(rows, "ratio", "generated", "640x480", f"{PEER_MOSSE} / {ELEMENT}", "median")
    share = value(rows, "clip", "generated", "1920x1080", "object", "share_of_frame")
    out = [
        (1, f"the element with its defaults (the flow model, {default}), 1920×1080 I420, "
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
