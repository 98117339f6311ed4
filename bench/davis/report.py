#!/usr/bin/python3
"""The DAVIS benchmark's report: from run.py's data, docs/davis.md (tables per sequence and
start, the means, the baselines and the published methods' J), its plot and contact sheets, and
with --summary the summary between the DAVIS markers in docs/measured.md. Every number is
computed from the run's data; what the run did not measure reads "not measured".

    report.py DATA_DIR DOC_DIR OUTPUT.md [--summary docs/measured.md]
"""
import argparse
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from report_kit import (DASH, MISSING, fmt_num, fmt_pct, fmt_res, frame_size,  # noqa: E402
                        missing, replace_between)

import cost  # noqa: E402
import dataset  # noqa: E402
import figures  # noqa: E402
import measures  # noqa: E402
import results as R  # noqa: E402

SUMMARY_BEGIN = "<!-- DAVIS summary: written by bench/davis/report.py -->"
SUMMARY_END = "<!-- end of DAVIS summary -->"


def fj(x):
    """J or F (0-1) as DAVIS writes it: 0-100, one decimal."""
    return fmt_num(None if missing(x) else 100 * x, 1)


def fms(x):
    return fmt_num(x, 1) if not missing(x) else MISSING


CELL = {"j": fj, "f": fj, "kept": fmt_pct, "ms": fms}
TITLE = {"j": "J (region IoU, 0–100)", "f": "F (boundary F-measure, 0–100)",
         "kept": "kept (share of frames)", "ms": "ms per frame (the tracker's call)"}


def intro(meta, res):
    n = res.scored_frames()
    quick = " (a quick run: " + str(meta["frame_limit"]) + " frames a sequence)" \
        if meta.get("frame_limit") else ""
    load = " at the start, ".join(str(x) for x in meta["machine"].get("load", [])) + " at the end" \
        if meta["machine"].get("load") else MISSING
    size_set = sorted(set(meta.get("sizes", {}).values()))
    sizes = ", ".join(fmt_res(z) for z in size_set) or MISSING
    tolerance = ", ".join(
        f"{math.ceil(measures.BOUND_TH * math.hypot(*frame_size(z)))} px at {fmt_res(z)}"
        for z in size_set) or MISSING
    model = meta["model"] or f"the module's default, `{meta['module']['settings'].get('model')}`"
    return f"""# projtrack on DAVIS 2016 (the development split)

Written by `./run bench --davis` (bench/davis/report.py) from the run of {meta['date']}{quick}:
every number below is computed from that run's data; "{MISSING}" marks what it did not measure.

**What it measures.** How well one object is followed on real footage no one here shot: the
{len(res.sequences)} sequences of `{os.path.basename(meta['data'])}/` in this run (davis-dev holds ten
of the twenty sequences of DAVIS 2016 val, Perazzi et al., CVPR 2016, with a mask of the object
on every frame; frames of {sizes} px here). projtrack (the Python module, `projtrack.Tracker`, object
model: {model}) is started on frame 0 in three ways — **from the first mask** (`init(frame, mask)`,
the benchmark's own start), **from its box** (the tight bounding box of the first mask) and
**from a click** at its deepest point (the maximum of the first mask's distance transform) — and
beside it run the baselines: the **first mask held still** on every frame, and OpenCV's **CSRT,
KCF, MOSSE and MedianFlow** started from the box (OpenCV {meta['opencv']}).

**The protocol** (DAVIS 2016, semi-supervised): frames 1 .. N-2 of every sequence are scored
({n} frames over {len(res.sequences)} sequences in this run).

- **J**: the intersection over union of the predicted and the true masks, averaged over the
  frames of a sequence, then over sequences; an empty prediction of an empty truth counts as 1.
  A box tracker's mask is its box, filled.
- **F**: DAVIS's boundary F-measure: the one-pixel boundaries of both masks (DAVIS's seg2bmap),
  a boundary pixel matched when the other boundary passes within ceil(0.008 × the diagonal) px
  ({tolerance}, by distance transform), F = 2PR/(P+R) of the matched shares; averaged as J.
- **kept**: the share of frames whose centroid lies within ¼·√(true area) of the true centroid
  **and** whose area is within [0.5, 2]× the true area (the real-footage benchmark's measure). A
  box tracker's kept compares its box with the true box (centres and areas). On a frame where
  the truth is empty (the object hidden), a frame is kept only if the prediction is empty too.
  projtrack's centroid and area are those it reports (`r.centroid`, `r.area`; a lost frame
  repeats the last measured ones, as the module does); its J and F use `r.mask` likewise.
- **ms**: time.perf_counter around the tracker's call on each frame (`track()`, `update()`),
  nothing else, averaged over every timed frame of every sequence; measured in this run on
  {meta['machine']['cores']} cores ({meta['machine']['cpu']}), shared with other work (load
  average {load}; OpenCV's threads: {meta.get('opencv_threads', MISSING)}): read the times as
  this run's, not as the trackers' cost on an idle machine. The held mask calls nothing: {DASH}.

The published J (the table of `davis-dev/README.md`, from the {dataset.PUBLISHED_SOURCE}) are
those methods' results started from the first mask.

**How to run.** `./run bench --davis [DIR]` (DIR in DAVIS layout: `JPEGImages/480p/<seq>/`,
`Annotations/480p/<seq>/`; default `../shared/davis-dev` beside the repository; a few minutes)
regenerates this page, its pictures in `docs/davis/`, its summary in `docs/measured.md` and the
README's table; `--model NAME` runs projtrack with another object model; `./run bench --davis
--quick` is a smoke run of two sequences and a few frames into the build folder, docs untouched. The raw per-frame data of the
run is `<build>/davis/frames.csv` (and `runs.csv`, `meta.json`); the doc folder keeps a copy
(`docs/davis/frames.csv.gz`).
"""


def means_table(res, published, methods):
    lines = ["| run | J | F | kept | ms per frame (mean) | ms per frame (median) |",
             "|---|---|---|---|---|---|"]
    for key in res.keys:
        cells = [CELL[m](res.overall(key, m)) if not (key[0] == "hold" and m == "ms") else DASH
                 for m in R.MEASURES]
        cells.append(fms(res.median_ms(key)) if key[0] != "hold" else DASH)
        note = ""
        if not all(res.measured(s, key) for s in res.sequences):
            note = " (not measured: below)" if res.note(key) else " (not on every sequence)"
        lines.append(f"| {R.LABELS[key]}{note} | " + " | ".join(cells) + " |")
    for m in methods:
        vals = [published[m].get(s) for s in res.sequences]
        j = R.mean(vals) if not missing(*vals) else None
        lines.append(f"| {m} (published, first mask) | {fmt_num(j, 1)} | {DASH} | {DASH} | "
                     f"{DASH} | {DASH} |")
    return lines


def per_sequence_table(res, measure, published=None, methods=()):
    keys = [k for k in res.keys if not (measure == "ms" and k[0] == "hold")]
    head = ["sequence"] + [R.SHORT[k] for k in keys] + [f"{m}*" for m in methods]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for s in res.sequences:
        cells = [CELL[measure](res.seq_mean(s, k, measure)) for k in keys]
        cells += [fmt_num(published[m].get(s), 1) for m in methods]
        lines.append(f"| {s} | " + " | ".join(cells) + " |")
    cells = [CELL[measure](res.overall(k, measure)) for k in keys]
    for m in methods:
        vals = [published[m].get(s) for s in res.sequences]
        cells.append(fmt_num(R.mean(vals) if not missing(*vals) else None, 1))
    lines.append("| **mean** | " + " | ".join(f"**{c}**" for c in cells) + " |")
    return lines


def sheet_frames(res, seq):
    """The frames of a sequence's sheet: 1, N/2, N-2 and the lowest J of the first-mask start
    (of the box start when the mask start was not measured), with why each is there."""
    n = res.meta["frames"][seq]
    start = ("projtrack", "mask") if res.measured(seq, ("projtrack", "mask")) \
        else ("projtrack", "box")
    worst = res.worst_frame(seq, start)
    why = {}
    for i, w in ((1, "first"), (n // 2, "N/2"), (n - 2, "N-2")):
        if 1 <= i <= n - 2:
            why.setdefault(i, w)
    if worst is not None:
        why[worst] = f"worst of {start[1]}"
    return sorted(why.items()), start[1]


def reading(res):
    """Sentences computed from the per-sequence J: where each projtrack start stands against the
    held first mask and CSRT, and where it scores (almost) nothing."""
    out = []
    for start in ("mask", "box", "click"):
        key = ("projtrack", start)
        if key not in res.keys or not any(res.measured(s, key) for s in res.sequences):
            continue
        seqs = [s for s in res.sequences if res.measured(s, key)]
        j = {s: res.seq_mean(s, key, "j") for s in seqs}
        parts = []
        for other in (("hold", "mask"), ("CSRT", "box")):
            if other not in res.keys:
                continue
            above = [s for s in seqs if res.measured(s, other) and j[s] > res.seq_mean(s, other, "j")]
            parts.append(f"above {R.READING[other]} on {len(above)} of "
                         f"{len(seqs)} sequences" + (f" ({', '.join(above)})" if above else ""))
        low = [s for s in seqs if j[s] < 0.05]
        parts.append(f"J below 5 on {len(low)}" + (f" ({', '.join(low)})" if low else ""))
        out.append(f"- {R.LABELS[key]}: " + "; ".join(parts) + ".")
    return out


def model_words(meta):
    """Which object model the run measured, in the summary's words."""
    model = meta["model"] or meta["module"]["settings"].get("object_model",
                                                           meta["module"]["settings"].get("model"))
    return f"object model `{model}`" + ("" if meta["model"] else ", the default")


def summary(res, published, methods, link="davis.md"):
    """The summary block of docs/measured.md (`link`: the path of docs/davis.md from there)."""
    def j(key):
        return fj(res.overall(key, "j"))
    pub = ", ".join(f"{m} {fmt_num(R.mean(published[m].get(s) for s in res.sequences), 1)}"
                    for m in methods[:2])
    return (f"On DAVIS 2016's development split ({len(res.sequences)} sequences, "
            f"[davis.md]({link}), run of {res.meta['date']}), J (region IoU, mean "
            f"over sequences of frames 1..N-2): projtrack ({model_words(res.meta)}) from the first mask "
            f"{j(('projtrack', 'mask'))}, from its box {j(('projtrack', 'box'))}, from a click "
            f"{j(('projtrack', 'click'))}; the first mask held still {j(('hold', 'mask'))}; "
            f"OpenCV CSRT from the box {j(('CSRT', 'box'))}; published (from the first mask): "
            f"{pub}.")


def write_doc(res, doc_dir, path):
    published, methods = dataset.published(res.meta["data"])
    lines = [intro(res.meta, res), "## The means", "",
             f"Over the {len(res.sequences)} sequences (J, F, kept: the mean of the sequences' "
             "means; ms: over every timed frame):", ""]
    lines += means_table(res, published, methods)
    missing_starts = [R.LABELS[k] for k in res.keys if res.note(k)]
    if missing_starts:
        lines += ["", "Not measured: " + "; ".join(f"{n} — {res.note(k)}" for k, n in
                                                    zip([k for k in res.keys if res.note(k)],
                                                        missing_starts)) + "."]
    lines += [""] + reading(res)
    plot = os.path.join(doc_dir, "j_per_sequence.png")
    figures.plot_j(res, published, methods, plot)
    rel = os.path.relpath(doc_dir, os.path.dirname(os.path.abspath(path)))
    lines += ["", f"![J per sequence: projtrack's starts, the held mask and CSRT beside the "
              f"published methods]({rel}/j_per_sequence.png)", ""]
    for m in R.MEASURES:
        lines += [f"## {TITLE[m]} per sequence", ""]
        if m == "j" and methods:
            lines += ["Starred columns: the published J (" + dataset.PUBLISHED_SOURCE + ").", ""]
        lines += per_sequence_table(res, m, published, methods if m == "j" else ()) + [""]
    lines += cost.cost_section(res)
    lines += ["## Contact sheets", "",
              "Per sequence, projtrack's mask outlined in magenta and the truth in green, one row "
              "per start, on frame 1, N/2, N-2 and the frame of the lowest J of the first-mask "
              "start (of the box start where the mask start was not measured); each tile's "
              "caption gives its start, frame and J.", ""]
    for s in res.sequences:
        frames, start = sheet_frames(res, s)
        name = f"sheet-{s}.jpg"
        if figures.sheet(res, s, frames, os.path.join(doc_dir, name)):
            worst = [i for i, w in frames if w.startswith("worst")]
            lines += [f"**{s}** (lowest J from the {start}: frame "
                      f"{worst[0] if worst else MISSING})", "",
                      f"![{s}: projtrack's masks (magenta) against the truth (green)]"
                      f"({rel}/{name})", ""]
        else:
            lines += [f"**{s}**: no projtrack run measured, no sheet.", ""]
    m = res.meta
    lines += ["## The run", "",
              f"- data: `{m['data']}`; sequences: {', '.join(res.sequences)}",
              f"- projtrack module {m['module']['version']} (`{os.path.basename(m['module']['file'])}`), "
              f"settings: " + ", ".join(f"{k}={v}" for k, v in m["module"]["settings"].items()),
              f"- OpenCV {m['opencv']}, Python {m['python']}; {m['machine']['system']}, "
              f"{m['machine']['cores']} cores",
              f"- the whole run (tracking and scoring, all runs): {m['seconds']:.0f} s"]
    with open(path, "w") as f:
        f.write("\n".join(lines).rstrip() + "\n")
    return published, methods


def rewrite_summary(path, block):
    replace_between(path, SUMMARY_BEGIN, SUMMARY_END, block, "bench/davis/report.py")


def main():
    ap = argparse.ArgumentParser()
    for a in ("data_dir", "doc_dir", "output"):
        ap.add_argument(a)
    ap.add_argument("--summary")
    a = ap.parse_args()
    res = R.Results(a.data_dir)
    os.makedirs(a.doc_dir, exist_ok=True)
    published, methods = write_doc(res, a.doc_dir, a.output)
    if os.path.abspath(a.doc_dir) != os.path.abspath(a.data_dir):
        import gzip
        for name in ("runs.csv", "meta.json"):
            shutil.copy(os.path.join(a.data_dir, name), os.path.join(a.doc_dir, name))
        with open(os.path.join(a.data_dir, "frames.csv"), "rb") as src, \
                gzip.GzipFile(os.path.join(a.doc_dir, "frames.csv.gz"), "wb", mtime=0) as dst:
            shutil.copyfileobj(src, dst)
    if a.summary:
        link = os.path.relpath(a.output, os.path.dirname(os.path.abspath(a.summary)))
        rewrite_summary(a.summary, summary(res, published, methods, link))


if __name__ == "__main__":
    main()
