#!/usr/bin/python3
"""Writes docs/real_footage.md from a real-footage run (./run bench --real).

Usage: bench/real/report.py DATA_DIR TRUTH_DIR DOC_DIR OUTPUT.md [--summary docs/measured.md]
       bench/real/report.py DATA_DIR TRUTH_DIR DOC_DIR OUTPUT.md --requests FILE

DATA_DIR holds prepare.py's plan and truth and projtrack-real's runs.csv, speed.csv, meta.json
and frames/ (the frames `projtrack-real --render` drew for the contact sheets). With --requests,
writes only the list of those frames (FILE) for projtrack-real. Otherwise writes OUTPUT.md and,
under DOC_DIR, sheets/ and the data (runs.csv.gz, speed.csv, meta.json, plan.csv, clips.csv);
with --summary, rewrites the block between the real-footage markers in docs/measured.md. Every
number and verdict is computed here from the measurements; missing data reads "not measured".
"""
import argparse
import gzip
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "common"))

import clip_set  # noqa: E402
import sections  # noqa: E402
from results import Results  # noqa: E402
from scoring import AREA_TOLERANCE, area_ratio, categories  # noqa: E402
from truth_geometry import read_outlines  # noqa: E402
from sheets import contact_sheet, pick_frames, slug, write_requests  # noqa: E402
from targets import GOAL_NO_SEED, START_TEXT  # noqa: E402
from report_kit import replace_between  # noqa: E402

SUMMARY_BEGIN = "<!-- real-footage summary: written by bench/real/report.py -->"
SUMMARY_END = "<!-- end of real-footage summary -->"
MOST_SHEETS = 6  # a clip's contact sheets, at most


def failing(res, entry, tracker, start):
    m = res.score_of(entry, tracker)
    if m is None:
        return False
    if start == "none":
        return res.one_mover(res.clip_of[entry]) and not m["kept"] >= GOAL_NO_SEED
    return not res.met(entry, tracker)


def chosen_sheets(res):
    """[(entry, tracker, start, frames)]: the telling shortfalls. On each clip as decoded every
    start that falls short (the worst quarter point for the four); on a variant the deepest point
    and the box when they fall short on the edge or half variant, or where the clip as decoded
    met them (the variant is the cause). At most MOST_SHEETS a clip, in priority()'s order."""
    out = []
    for clip in res.clips:
        mine = []
        for entry in res.entries_of(clip):
            variant = res.variant[entry]
            for start in (["deepest", "quarter", "box", "none"] if not variant
                          else ["deepest", "box"]):
                names = res.start_runs(entry, start)
                name = res.worst_quarter(entry) if start == "quarter" else \
                    (names[0] if names else None)
                if not name or not failing(res, entry, name, start):
                    continue
                base = res.start_runs(clip, start)
                if variant not in ("", "edge", "half") and base and \
                        not res.met(clip, base[0]):
                    continue
                frames = res.score_of(entry, name)["missed_frames"] or off_area(res, entry, name)
                mine.append((entry, name, start, pick_frames(frames)))
        mine.sort(key=lambda s: priority(res.variant[s[0]], s[2]))
        out += mine[:MOST_SHEETS]
    return out


FIRST = [("", "deepest"), ("", "box"), ("edge", "deepest"), ("edge", "box"), ("half", "deepest"),
         ("", "quarter"), ("", "none"), ("half", "box")]


def priority(variant, start):
    """The order in which a clip's shortfalls get one of its MOST_SHEETS sheets: the clip as
    decoded and the edge and half variants first, then the lighting variants."""
    return (FIRST.index((variant, start)) if (variant, start) in FIRST else len(FIRST),
            clip_set.ALL_VARIANTS.index(variant) if variant in clip_set.ALL_VARIANTS else -1)


def off_area(res, entry, name):
    """The in-view frames whose area is off by more than ±25 % (a run kept on every frame that
    misses the area target)."""
    by = {r["frame"]: r for r in res.runs[(entry, name)]}
    return [i for i, t in enumerate(res.truth[entry])
            if t["area"] and not abs(area_ratio(by.get(i), t) - 1) <= AREA_TOLERANCE]


class Document:
    def __init__(self, res, doc_dir, path):
        self.res, self.doc_dir = res, doc_dir
        self.rel = os.path.relpath(doc_dir, os.path.dirname(os.path.abspath(path)))
        self.lines = []

    def w(self, line=""):
        self.lines.append(line)

    def sheet_section(self):
        res = self.res
        self.w("## Where it falls short")
        self.w()
        self.w("Every run of the default method on a clip as decoded that misses a target, and "
               "on a variant the deepest-point and box starts where the edge or half variant "
               "misses, or where the clip as decoded met the targets and the variant does not. "
               "Each tile is the element's own overlay (draw=true: its outline, box and status), "
               "the true silhouette in green with its centroid as a green dot; the caption "
               "gives the frame, the miss's category, the reported area as a multiple of the "
               "true one and how far the centroid is off, or the status when nothing was "
               "measured. A small object is shown in a crop around it, enlarged.")
        self.w()
        shown = 0
        for entry, name, start, frames in chosen_sheets(res):
            m = res.score_of(entry, name)
            path = f"sheets/{entry}-{slug(name)}.jpg"
            made = contact_sheet(
                os.path.join(res.data_dir, "frames", entry, slug(name)), res.runs[(entry, name)],
                res.truth[entry], outlines(res.data_dir, entry), frames,
                os.path.join(self.doc_dir, path), overlay=True)
            self.w(f"### {entry}: {START_TEXT[start]}")
            self.w()
            self.w(f"`{res.props(entry, name) or name}`: " + sections.run_line(m))
            cats = categories(res.runs[(entry, name)], res.truth[entry])
            if cats:
                self.w()
                self.w("Missed frames: " + "; ".join(
                    f"{len(f)} {k} ({sections.ranges(f)})" for k, f in
                    sorted(cats.items(), key=lambda kv: -len(kv[1]))) + ".")
            self.w()
            self.w(f"![{entry}, {name}]({self.rel}/{path})" if made else
                   "No contact sheet: its frames were not rendered.")
            self.w()
            shown += 1
        if not shown:
            self.w("None: every start meets its targets.")
            self.w()

    def write(self, path):
        res = self.res
        os.makedirs(os.path.join(self.doc_dir, "sheets"), exist_ok=True)
        self.w("# Real footage")
        self.w()
        self.w("<!-- Generated by bench/real/report.py from `./run bench --real`: do not edit. -->")
        self.w()
        sections.header(self)
        sections.targets(self)
        for clip in res.clips:
            sections.clip(self, clip)
        self.sheet_section()
        sections.static(self)
        sections.speed(self)
        sections.cut_short(self)
        with open(path, "w") as f:
            f.write("\n".join(self.lines).rstrip() + "\n")


def outlines(data_dir, entry):
    p = os.path.join(data_dir, "truth", entry + "_outlines.csv.gz")
    return read_outlines(p) if os.path.exists(p) else {}


def rewrite_summary(path, block):
    replace_between(path, SUMMARY_BEGIN, SUMMARY_END, block, "bench/real/report.py")


def copy_data(data_dir, doc_dir):
    for name in ("speed.csv", "meta.json", "plan.csv", "clips.csv", "seeds.csv"):
        if os.path.exists(os.path.join(data_dir, name)):
            shutil.copy(os.path.join(data_dir, name), os.path.join(doc_dir, name))
    with open(os.path.join(data_dir, "runs.csv"), "rb") as src, \
            gzip.GzipFile(os.path.join(doc_dir, "runs.csv.gz"), "wb", mtime=0) as dst:
        shutil.copyfileobj(src, dst)


def main():
    ap = argparse.ArgumentParser()
    for a in ("data_dir", "truth_dir", "doc_dir", "output"):
        ap.add_argument(a)
    ap.add_argument("--summary")
    ap.add_argument("--requests")
    a = ap.parse_args()
    res = Results(a.data_dir)
    if a.requests:
        write_requests(a.requests, [(e, n, res.props(e, n), f)
                                    for e, n, _, f in chosen_sheets(res)])
        return
    doc = Document(res, a.doc_dir, a.output)
    doc.write(a.output)
    if os.path.abspath(a.doc_dir) != os.path.abspath(a.data_dir):
        copy_data(a.data_dir, a.doc_dir)
    if a.summary:
        link = os.path.relpath(a.output, os.path.dirname(os.path.abspath(a.summary)))
        rewrite_summary(a.summary, sections.summary(res, link))


if __name__ == "__main__":
    main()
