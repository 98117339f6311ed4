#!/usr/bin/python3
"""The README's table of measured numbers, beside OpenCV's CSRT, KCF and MOSSE, from the
benchmarks' committed data: never typed by hand.

    readme_table.py [--root SOURCE_DIR]            # rewrite README.md's block between the markers
    readme_table.py --check [--root SOURCE_DIR]    # fail when the block differs from the data's
    readme_table.py --print [--root SOURCE_DIR]    # print the block

It reads
- docs/real_footage/runs.csv.gz, plan.csv and meta.json (`./run bench --real`) with the clips'
  truth in bench/real/truth/: per clip as decoded, the share of frames kept from the object's
  box, scored as bench/real/scoring.py scores them;
- docs/davis/frames.csv.gz, runs.csv and meta.json (`./run bench --davis`): J per start, as
  bench/davis/results.py averages it, and which object model the run measured;
- docs/performance/speed.csv and meta.json (`./run bench --speed`): the element's and MOSSE's
  time per frame on a real clip at 640×480, measured side by side.

Whatever the data does not hold reads "not measured". Each of those reports calls this after
writing its data (bench/real/report.py, bench/davis/report.py, bench/speed/report.py), and so does
`./run docs`; tests/bench/test_readme_table.py checks that README.md matches the committed data.
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
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
from report_kit import MISSING, fmt_num, fmt_pct, missing, replace_between  # noqa: E402

BEGIN = "<!-- measured: written by bench/common/readme_table.py from the benchmarks' data -->"
END = "<!-- end of measured -->"
DASH = "—"  # a start the tracker does not take
PEERS = ["CSRT", "KCF", "MOSSE"]
BOX = "projtrack start-box"


def _import(folder, name):
    """A module of bench/<folder>/ (each benchmark's folder is its own import root)."""
    path = os.path.join(ROOT, "bench", folder)
    sys.path.insert(0, path)
    try:
        return __import__(name)
    finally:
        sys.path.remove(path)


# ---- real footage ------------------------------------------------------------------------------

def real_footage(root):
    """{"clips": [(name, what)], "kept": {tracker: {clip: share}}, "centroid": {...},
    "ms": {tracker: median ms}, "date": str} of the clips as decoded; {} without data."""
    d = os.path.join(root, "docs", "real_footage")
    runs_path, plan_path = os.path.join(d, "runs.csv.gz"), os.path.join(d, "plan.csv")
    if not (os.path.exists(runs_path) and os.path.exists(plan_path)):
        return {}
    scoring = _import("real", "scoring")
    clip_set = _import("real", "clip_set")
    with open(plan_path, newline="") as f:
        clips = [p["entry"] for p in csv.DictReader(f) if not p["variant"]]
    trackers = [BOX] + [f"cvtracker {p}" for p in PEERS]
    runs = {}
    with gzip.open(runs_path, "rt", newline="") as f:
        for r in csv.DictReader(f):
            if r["clip"] not in clips or r["tracker"] not in trackers:
                continue
            for k in scoring.INTS:
                r[k] = int(r[k])
            for k in scoring.FLOATS:
                r[k] = float(r[k]) if r.get(k, "") != "" else math.nan
            runs.setdefault((r["clip"], r["tracker"]), []).append(r)
    truth_dir = os.path.join(root, "bench", "real")
    out = {"clips": [], "kept": {}, "centroid": {}, "ms": {}, "date": ""}
    meta_path = os.path.join(d, "meta.json")
    if os.path.exists(meta_path):
        with open(meta_path) as f:
            meta = json.load(f)
        out["date"], out["cores"] = meta.get("measured", ""), meta.get("cores")
    for c in clips:
        truth = scoring.load_truth(truth_dir, c)
        if not truth:
            continue
        what = clip_set.BY_NAME[c].what if c in clip_set.BY_NAME else c
        out["clips"].append((c, what))
        for t in trackers:
            rows = sorted(runs.get((c, t), []), key=lambda r: r["frame"])
            m = scoring.score(rows, truth) if rows else None
            out["kept"].setdefault(t, {})[c] = m["kept"] if m else math.nan
            out["centroid"].setdefault(t, {})[c] = m["kept_old"] if m else math.nan
    for t in trackers:
        us = [r["us"] for c, _ in out["clips"] for r in runs.get((c, t), [])
              if not missing(r["us"])]
        out["ms"][t] = statistics.median(us) / 1000 if us else math.nan
    return out


# ---- DAVIS 2016 --------------------------------------------------------------------------------

def davis(root):
    """{"j": {(tracker, start): mean J}, "sequences": n, "model": str, "date": str}; {} without
    data."""
    d = os.path.join(root, "docs", "davis")
    names = ("frames.csv.gz", "runs.csv", "meta.json")
    if not all(os.path.exists(os.path.join(d, n)) for n in names):
        return {}
    results = _import("davis", "results")
    with tempfile.TemporaryDirectory() as tmp:
        with gzip.open(os.path.join(d, "frames.csv.gz"), "rb") as src, \
                open(os.path.join(tmp, "frames.csv"), "wb") as dst:
            shutil.copyfileobj(src, dst)
        for n in names[1:]:
            shutil.copy(os.path.join(d, n), tmp)
        res = results.Results(tmp)
    keys = [("projtrack", "mask"), ("projtrack", "box"), ("projtrack", "click")] + \
        [(p, "box") for p in PEERS]
    settings = res.meta.get("module", {}).get("settings", {})
    model = res.meta.get("model") or settings.get("object_model", settings.get("model", ""))
    return {"j": {k: res.overall(k, "j") for k in keys}, "sequences": len(res.sequences),
            "model": model, "date": res.meta.get("date", ""),
            "cores": res.meta.get("machine", {}).get("cores")}


# ---- speed -------------------------------------------------------------------------------------

def speed(root):
    """{"ms": {"projtrack": ms, "MOSSE": ms}, "date": str} at 640×480 on the real clip (the
    element's default settings, MOSSE through cvtracker); {} without data."""
    path = os.path.join(root, "docs", "performance", "speed.csv")
    if not os.path.exists(path):
        return {}
    want = {"projtrack element default": "projtrack", "cvtracker MOSSE": "MOSSE"}
    out = {"ms": {}, "date": ""}
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            if (r["section"], r["clip"], r["resolution"], r["key"]) == \
                    ("per_frame", "real", "640x480", "median_us") and r["what"] in want:
                out["ms"][want[r["what"]]] = float(r["value"]) / 1000
    meta = os.path.join(root, "docs", "performance", "meta.json")
    if os.path.exists(meta):
        with open(meta) as f:
            meta = json.load(f)
        out["date"], out["cores"] = meta.get("measured", ""), meta.get("cores")
    return out


# ---- the block ---------------------------------------------------------------------------------

def row(on, measured, cells):
    return "| " + " | ".join([on, measured] + list(cells)) + " |"


def mean_or_nan(values):
    values = list(values)
    return math.nan if not values or missing(*values) else sum(values) / len(values)


def block(root=ROOT):
    real, dv, sp = real_footage(root), davis(root), speed(root)
    out = ["| on | measured | projtrack | CSRT | KCF | MOSSE |", "|---|---|---|---|---|---|"]
    trackers = [BOX] + [f"cvtracker {p}" for p in PEERS]
    clips = real.get("clips", [])
    what = dict(clips)

    def right(clip=None):
        """'kept (centroid only)' per tracker, of one clip or the mean over the clips."""
        cells = []
        for t in trackers:
            k, c = real.get("kept", {}).get(t, {}), real.get("centroid", {}).get(t, {})
            if clip is None:
                kv = mean_or_nan(k.get(x, math.nan) for x, _ in clips)
                cv = mean_or_nan(c.get(x, math.nan) for x, _ in clips)
            else:
                kv, cv = k.get(clip, math.nan), c.get(clip, math.nan)
            cells.append(MISSING if missing(kv) else f"{fmt_pct(kv)} ({fmt_pct(cv)})")
        return cells

    for c in ("cup", "box"):
        out.append(row(f"{what.get(c, c)}, started from its box", "frames right (centroid only)",
                       right(c) if c in what else [MISSING] * 4))
    n = f"all {len(clips)} real clips" if clips else "the real clips"
    out.append(row(f"{n}, started from the box", "frames right (centroid only), mean",
                   right() if clips else [MISSING] * 4))
    out.append(row(f"{n}", "time per frame, median",
                   [fmt_num(real.get("ms", {}).get(t), 1, " ms") for t in trackers]))
    j = dv.get("j", {})

    def fj(x):
        return fmt_num(None if x is None or missing(x) else 100 * x, 1)
    davis_on = f"DAVIS 2016, {dv['sequences']} sequences" if dv else "DAVIS 2016"
    out.append(row(f"{davis_on}, started from the box", "J",
                   [fj(j.get(("projtrack", "box")))] + [fj(j.get((p, "box"))) for p in PEERS]))
    out.append(row(f"{davis_on}, started from the first mask", "J",
                   [fj(j.get(("projtrack", "mask")))] + [DASH] * 3))
    out.append(row(f"{davis_on}, started from a click", "J",
                   [fj(j.get(("projtrack", "click")))] + [DASH] * 3))
    ms = sp.get("ms", {})
    out.append(row("a real clip at 640×480, side by side", "time per frame, median",
                   [fmt_num(ms.get("projtrack"), 2, " ms"), MISSING, MISSING,
                    fmt_num(ms.get("MOSSE"), 2, " ms")]))
    scoring = _import("real", "scoring")
    model = (f" projtrack ran its `{dv['model']}` object model on DAVIS, its default "
             "elsewhere." if dv.get("model") else "")

    def run(name, data):
        cores = f" ({data['cores']} cores)" if data.get("cores") else ""
        return f"{name} {data['date']}{cores}" if data.get("date") else ""
    when = "; ".join(s for s in (run("real footage", real), run("DAVIS", dv),
                                 run("speed", sp)) if s)
    within = f"{scoring.WITHIN:g}·√area"
    ratio = f"{scoring.AREA_MIN:g}–{scoring.AREA_MAX:g}×"
    out += ["", "A frame is **right** (the reports' \"kept\") when the centroid is within "
            f"{within} of the true one and the area within {ratio} the true area (a box "
            "tracker's area is its box's, so \"centroid only\" is the fairer comparison for "
            "them); **J** is DAVIS's overlap of the reported silhouette with the true one "
            f"(0–100; a box tracker's silhouette is its box).{model} CSRT, KCF and MOSSE are "
            "OpenCV's, started from the same box; \"" + DASH + "\": they take no mask or "
            "click; \"" + MISSING + "\": not in the data. Runs: " + (when or MISSING) + "."]
    return "\n".join(out)


def rewrite(path, text):
    """Writes the table into README.md; True when it changed."""
    return replace_between(path, BEGIN, END, text, "readme_table.py")


def shown(path):
    """The block README.md holds now, or None without markers."""
    doc = open(path).read()
    if BEGIN not in doc or END not in doc:
        return None
    return doc.split(BEGIN, 1)[1].split(END, 1)[0].strip("\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--readme", help="default: ROOT/README.md")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--print", action="store_true")
    a = ap.parse_args()
    readme = a.readme or os.path.join(a.root, "README.md")
    text = block(a.root)
    if a.print:
        print(text)
        return 0
    if a.check:
        now = shown(readme)
        if now != text:
            print(f"{readme}: the measured table differs from the benchmarks' data "
                  "(bench/common/readme_table.py rewrites it):")
            print("shown:\n" + str(now) + "\n\nfrom the data:\n" + text)
            return 1
        print(f"{readme}: the measured table matches the benchmarks' data")
        return 0
    if rewrite(readme, text):
        print(f"readme_table.py: updated {readme}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
