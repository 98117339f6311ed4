"""The bounded-work and work-per-frame sections of docs/performance.md (bench/speed/report.py)."""
from report_kit import DASH, MISSING, fmt_res, fmt_x, missing
from speed_data import BOUNDED_RES, fmt_us, value
from speed_targets import adversarial_by_method, extreme_rows, interrupt_values


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
