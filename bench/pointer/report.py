#!/usr/bin/python3
"""Writes docs/pointer.md from the 3D-mouse benchmark's run (./run bench --pointer).

Usage: bench/pointer/report.py DATA_DIR DOC_DIR OUTPUT.md [--tracker-doc docs/tracker.md]

Reads DATA_DIR/frames.csv, truth.csv and meta.json (bench/pointer/run.py); writes OUTPUT.md, its
figures under DOC_DIR/figures and the data it rests on (frames.csv.gz, truth.csv, meta.json)
under DOC_DIR. With --tracker-doc, rewrites that file's block between the gesture markers with
the summary. Every number and verdict comes from the run; missing data reads "not measured" and
counts as a miss.
"""
import argparse
import gzip
import os
import shutil
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
import scene  # noqa: E402
import scoring  # noqa: E402
import script  # noqa: E402
from report_kit import MISSING, TARGET, fmt_num, fmt_pct, load_meta, verdict  # noqa: E402
import figures  # noqa: E402

KINDS = ("push", "press", "release")
SUMMARY_BEGIN = "<!-- pointer summary: written by bench/pointer/report.py -->"
SUMMARY_END = "<!-- end of pointer summary -->"


def score(data_dir):
    """Everything the document shows: per sequence its scored truths, false reports and quiet
    margin; per clip its frames, tracked frames, reports and margin."""
    frames = scoring.load_frames(os.path.join(data_dir, "frames.csv"))
    truth = scoring.load_truth(os.path.join(data_dir, "truth.csv"))
    meta = load_meta(data_dir)
    seqs, clips = [], []
    for s in meta["sequences"]:
        rows = frames.get(("sequence", s["name"]), [])
        scored, false, quiet = scoring.score_sequence(rows, truth.get(s["name"], []))
        if not rows:  # not run: every gesture of it is missed
            scored = [dict(t, latency=None, tracked=False, excess=None)
                      for t in truth.get(s["name"], [])]
        seqs.append(dict(s, rows=rows, truths=scored, false=false, quiet=quiet))
    for name, c in meta["clips"].items():
        rows = frames.get(("clip", name), [])
        _, false, quiet = scoring.score_sequence(rows, [])
        held = sum(r["status"] in scoring.TRACKING for r in rows)
        clips.append(dict(name=name, path=c["path"], rows=rows, frames=len(rows), held=held,
                          false=false, quiet=quiet, width=c.get("width"),
                          height=c.get("height")))
    return meta, seqs, clips


def found(truths):
    return sum(t["latency"] is not None for t in truths)


def share(n, total):
    return n / total if total else float("nan")


def ratio_text(n, total, none="none to find"):
    """'n of total'; `none` when there was nothing to find."""
    return f"{n} of {total}" if total else none


def latency_text(truths):
    lat = [abs(t["latency"]) for t in truths if t["latency"] is not None]
    if not lat:
        return MISSING
    return f"{statistics.median(lat):.2f} / {max(lat):.2f} s"


def all_truths(seqs, pick=lambda s, t: True):
    return [t for s in seqs for t in s["truths"] if pick(s, t)]


def visible(t):
    """Held, and its rise over the depth's trend reached the threshold (a release: its press's)."""
    return t["tracked"] and t["excess"] is not None and t["excess"] >= 1


def targets_table(seqs, clips):
    """The issue's targets, each with its measure and verdict."""
    truths = all_truths(seqs)
    tracked = [t for t in truths if t["tracked"]]
    shown = [t for t in truths if visible(t)]
    false = sum(len(s["false"]) for s in seqs)
    clip_gestures = sum(len(c["false"]) for c in clips)
    runs = [s for s in seqs if s["rows"]]
    rows = [
        ("every gesture found within ±0.4 s, every size, depth and duration",
         f"{ratio_text(found(truths), len(truths), MISSING)} found",
         verdict([share(found(truths), len(truths))], lambda x: x == 1, words=TARGET)),
        ("— of them, those through which the element held the object",
         f"{ratio_text(found(tracked), len(tracked), MISSING)} found",
         verdict([share(found(tracked), len(tracked))], lambda x: x == 1, words=TARGET)),
        ("— of those, the gestures whose depth rose past the threshold over its trend",
         f"{ratio_text(found(shown), len(shown), MISSING)} found",
         verdict([share(found(shown), len(shown))], lambda x: x == 1, words=TARGET)),
        ("no false gesture on the sequences",
         f"{false} false" if runs else MISSING,
         verdict([false if runs else None], lambda x: x == 0, words=TARGET)),
        ("no gesture at all on " + ", ".join(c["name"] for c in clips),
         ", ".join(f"{c['name']} {len(c['false']) if c['frames'] else MISSING}" for c in clips),
         verdict([clip_gestures if all(c["frames"] for c in clips) and clips else None],
                 lambda x: x == 0, words=TARGET)),
    ]
    out = ["| target | measured | verdict |", "|---|---|---|"]
    out += [f"| {a} | {b} | {c} |" for a, b, c in rows]
    return "\n".join(out)


def kinds_table(seqs):
    out = ["| gesture | true | found | held by the element | found of those held | "
           "latency, median / worst |", "|---|---|---|---|---|---|"]
    for kind in KINDS:
        ts = all_truths(seqs, lambda s, t, k=kind: t["kind"] == k)
        held = [t for t in ts if t["tracked"]]
        out.append(f"| {kind} | {len(ts)} | {fmt_pct(share(found(ts), len(ts)))} | "
                   f"{len(held)} | {ratio_text(found(held), len(held))} | {latency_text(ts)} |")
    return "\n".join(out)


def by_table(seqs, label, key, values, fmt):
    """Gestures found (all, and of those held) and false reports for each value of `key`."""
    out = [f"| {label} | sequences | gestures found | found of those held | false |",
           "|---|---|---|---|---|"]
    for v in values:
        sel = [s for s in seqs if s[key] == v]
        ts = all_truths(sel)
        held = [t for t in ts if t["tracked"]]
        false = sum(len(s["false"]) for s in sel)
        out.append(f"| {fmt(v)} | {len(sel)} | {ratio_text(found(ts), len(ts))} | "
                   f"{ratio_text(found(held), len(held))} | {false} |")
    return "\n".join(out)


def push_grid(seqs, script_depths, script_durations):
    """Single pushes found of those held, by scripted depth × duration (nearest grid cell)."""
    def cell(x, grid):
        return min(grid, key=lambda g: abs(g - x))
    counts = {}
    for t in all_truths(seqs, lambda s, t: t["kind"] == "push" and t["tracked"]):
        k = (cell(t["depth"], script_depths), cell(t["duration"], script_durations))
        n, f = counts.get(k, (0, 0))
        counts[k] = (n + 1, f + (t["latency"] is not None))
    head = "| push depth \\ duration | " + " | ".join(f"{d:.2f} s" for d in script_durations) + " |"
    out = [head, "|---" * (len(script_durations) + 1) + "|"]
    for p in script_depths:
        cells = [f"{counts[(p, d)][1]} of {counts[(p, d)][0]}" if (p, d) in counts else MISSING
                 for d in script_durations]
        out.append(f"| +{100 * p:.0f} % | " + " | ".join(cells) + " |")
    return "\n".join(out)


def sequences_table(seqs):
    out = ["| sequence | object on | size | drift | noise | frames held | gestures found | "
           "false |", "|---|---|---|---|---|---|---|---|"]
    for s in seqs:
        rows = s["rows"]
        held = share(sum(r["status"] in scoring.TRACKING for r in rows), len(rows))
        false = ", ".join(f"{k} {t:.2f} s" for k, t in s["false"]) or "none"
        out.append(f"| {s['name']} | {s['object']} on {s['background']} | "
                   f"{100 * s['size']:.0f} % | ±{100 * s['drift']:.0f} % | {s['noise']:g} | "
                   f"{fmt_pct(held)} | {ratio_text(found(s['truths']), len(s['truths']))} | "
                   f"{false if rows else MISSING} |")
    return "\n".join(out)


def clips_table(clips):
    out = ["| clip | frames | frames held | push | press | release | largest rise ÷ threshold |",
           "|---|---|---|---|---|---|---|"]
    for c in clips:
        n = {k: sum(kind == k for kind, _ in c["false"]) for k in KINDS}
        out.append(f"| {c['name']} | {c['frames'] or MISSING} | "
                   f"{fmt_pct(share(c['held'], c['frames']))} | " +
                   " | ".join(str(n[k]) if c["frames"] else MISSING for k in KINDS) +
                   f" | {fmt_num(c['quiet'], 2)} |")
    return "\n".join(out)


def margins_text(seqs, clips):
    """How far the rules were from failing: the weakest found gesture, the strongest rise that
    was no gesture, the worst latency against the tolerance."""
    ex = [t["excess"] for t in all_truths(seqs, lambda s, t: visible(t) and t["latency"] is not None)]
    quiet = [s["quiet"] for s in seqs if s["quiet"] is not None] + \
        [c["quiet"] for c in clips if c["quiet"] is not None]
    lat = [abs(t["latency"]) for t in all_truths(seqs) if t["latency"] is not None]
    return "\n".join([
        f"- The weakest gesture found rose {fmt_num(min(ex) if ex else None, 2)}× the threshold "
        "above the depth's trend (1×: where a rise starts to count; measured by the report, "
        "as docs/tracker.md states the rule).",
        f"- Away from every gesture (the sequences' quiet stretches and the real clips) the depth "
        f"rose at most {fmt_num(max(quiet) if quiet else None, 2)}× the threshold above its trend; "
        "what keeps such a rise from being a gesture is then the other rules (two frames, the "
        "whole box grows, quick, back or a plateau).",
        f"- The latest gesture found came {fmt_num(max(lat) if lat else None, 2)} s from its "
        f"true time, against the ±{scoring.TOLERANCE} s tolerance."])


def method_text(meta, seqs):
    """How the sequences are made and scored, from the script's constants and the run's meta."""
    first = meta["sequences"][0] if meta["sequences"] else {}
    idle = [s for s in seqs if not s["truths"]]
    drifts = [s["drift"] for s in seqs]
    return f"""{len(seqs) - len(idle)} scripted sequences with {len(all_truths(seqs))} true gestures,
and {len(idle)} without any: real photographed objects ({", ".join(scene.OBJECT_WORDS.values())})
cut out of opencv-doc's images by a mask the benchmark makes (GrabCut from a rectangle, its
largest piece, holes filled) and moved over opencv-doc's photographs,
{first.get("width", MISSING)}×{first.get("height", MISSING)} at {first.get("fps", MISSING)} fps,
through the element with its default settings (started from the object's box on the first frame,
as a user shows it the object; the frames converted to I420 as a decoder gives them). The object
always moves in x and y (also during every gesture; a drag moves it sideways while pressed), turns
by ±4°, is smeared by motion blur (drawn at four instants across half a frame); the light drifts
by ±8 % and sensor noise is added. Its depth drifts slowly (a sine of ±{100 * min(drifts):.0f} to
±{100 * max(drifts):.0f} % over 8 to 12 s) and makes the gestures:

- pushes of +{100 * min(script.PUSH_DEPTHS):.0f} to +{100 * max(script.PUSH_DEPTHS):.0f} % in scale
  over {min(script.PUSH_DURATIONS):g} to {max(script.PUSH_DURATIONS):g} s (a raised cosine): every
  pair of {", ".join(f"+{100 * p:.0f} %" for p in script.PUSH_DEPTHS)} by
  {", ".join(f"{d:g} s" for d in script.PUSH_DURATIONS)} once per object size, two more of random
  depth and duration per sequence, and a double push (two short ones 0.15 to 0.35 s apart). A
  push is true at its peak;
- a press: forward by +15 to +50 % over 0.15 to 0.3 s, held 1 to 2 s while dragged sideways,
  back over 0.15 to 0.3 s. The press is true when the object is forward, the release when it is
  back.

The sequences without a gesture are a hand pointing around while its depth drifts by
±{100 * max(drifts):.0f} %, one per object size. The truth of every frame (the object's scale,
centre and area) is the script's: nothing of it is measured. An object's size is its larger side
at rest as a share of the frame's height. A gesture is found when the element reported one of its
kind within ±{scoring.TOLERANCE} s of its true time; every report that matches none is false. The
element held the object through a gesture when it reported it on
{fmt_pct(scoring.HELD_SHARE)} of the frames from {scoring.AROUND} s before the gesture to
{scoring.AROUND} s after it, its area within {scoring.HELD_AREA:g}× of its usual ratio to the true
area and that ratio at least {scoring.HELD_WHOLE:g} (a piece of the object is not the object): a
gesture the tracker did not follow cannot be read from depth. Its depth rose past the
threshold when, measured here as [tracker.md](tracker.md#gestures) states the rule, its rise over
the depth's trend reached max(7 %, 5 × the noise about the trend): below that, the rules are
meant not to see it."""


def write_doc(path, meta, seqs, clips, figs):
    text = f"""# The 3D mouse: clicks and drags from depth

Generated by `bench/pointer/report.py` from `./run bench --pointer` (its data: [pointer/](pointer/)):
every number here is the run's, never typed. The rules measured are [tracker.md](tracker.md#gestures)'s:
a push (forward and back) is a click, a press (forward and held) … release (back) a drag.

## Targets

{targets_table(seqs, clips)}

## How the benchmark is made

{method_text(meta, seqs)}

![depth and gestures]({figs[0]})

*Depth as the element reported it (√(area ÷ the frame's area), blue) and the truth (the script's,
scaled to it, grey); true gestures dashed, reported ones solid: push green, press red, release
violet. For each object size, the sequence the element held best.*

## By gesture

{kinds_table(seqs)}

## By object size

{by_table(seqs, "object size", "size", script.SIZES, lambda v: f"{100 * v:.0f} %")}

## By drift

{by_table(seqs, "drift of depth", "drift", sorted({s["drift"] for s in seqs}),
          lambda v: f"±{100 * v:.0f} %")}

## Pushes by depth and duration

Single pushes the element held, found of them, by their scripted depth and duration (the random
ones and the double pushes in the nearest cell):

{push_grid(seqs, script.PUSH_DEPTHS, script.PUSH_DURATIONS)}

## Every sequence

{sequences_table(seqs)}

## Real clips without a gesture

opencv-doc's clips through the element with its default settings (automatic acquisition), as the
real-footage benchmark runs it: every gesture reported is false.

{clips_table(clips)}

![depth on real clips]({figs[1]})

## Margins

{margins_text(seqs, clips)}

Run: {meta.get("gstreamer", MISSING)}, {meta.get("seconds", MISSING)} s.
"""
    with open(path, "w") as f:
        f.write(text)


def summary_block(seqs, clips):
    return "\n".join([SUMMARY_BEGIN, "", targets_table(seqs, clips), "", kinds_table(seqs), "",
                      SUMMARY_END])


def rewrite_block(path, block):
    with open(path) as f:
        text = f.read()
    a, b = text.find(SUMMARY_BEGIN), text.find(SUMMARY_END)
    if a < 0 or b < a:
        raise SystemExit(f"report.py: {path} has no pointer summary markers")
    with open(path, "w") as f:
        f.write(text[:a] + block + text[b + len(SUMMARY_END):])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("data_dir")
    ap.add_argument("doc_dir")
    ap.add_argument("output")
    ap.add_argument("--tracker-doc")
    args = ap.parse_args()
    meta, seqs, clips = score(args.data_dir)
    os.makedirs(os.path.join(args.doc_dir, "figures"), exist_ok=True)
    rel = os.path.relpath(args.doc_dir, os.path.dirname(os.path.abspath(args.output)))
    figs = figures.draw(seqs, clips, os.path.join(args.doc_dir, "figures"))
    if os.path.abspath(args.doc_dir) != os.path.abspath(args.data_dir):
        with open(os.path.join(args.data_dir, "frames.csv"), "rb") as src, \
                gzip.GzipFile(os.path.join(args.doc_dir, "frames.csv.gz"), "wb", mtime=0) as dst:
            shutil.copyfileobj(src, dst)
        for name in ("truth.csv", "meta.json"):
            shutil.copy(os.path.join(args.data_dir, name), args.doc_dir)
    write_doc(args.output, meta, seqs, clips, [os.path.join(rel, "figures", f) for f in figs])
    if args.tracker_doc:
        rewrite_block(args.tracker_doc, summary_block(seqs, clips))


if __name__ == "__main__":
    main()
