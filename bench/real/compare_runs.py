#!/usr/bin/python3
"""Compares two projtrack-real runs of the same plan, start by start: what a change to the
tracker does to every start of every clip and variant (a commit that changes the tracker reports
it).

Usage: bench/real/compare_runs.py PLAN_DIR BEFORE_DIR AFTER_DIR [--json OUT.json]

PLAN_DIR is prepare.py's plan (plan.csv, seeds.csv, truth/); BEFORE_DIR and AFTER_DIR each hold a
runs.csv of projtrack-real. Every (entry, tracker) of the default method is scored with
scoring.py ("kept": centroid within ¼√area and area within [0.5, 2]× the truth's, on in-view
frames) and the two runs compared: pairs better / worse by more than 2 points, the mean kept per
start kind, the worst pairs, a line per clip, and the static (background) frames reported by the
no-seed runs (scoring.run_stats).
"""
import argparse
import csv
import json
import math
import os
import re
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from scoring import load_runs, load_truth, run_stats, score  # noqa: E402

CLIPS = ["cup", "box", "balle1", "inertie", "force", "magnet", "cube", "ellipse", "vtest",
         "megamind"]
KINDS = ["deepest", "quarter", "box", "none"]
MARGIN = 0.02


def kind_of(tracker):
    if tracker.startswith("projtrack quarter"):
        return "quarter"
    if tracker == "projtrack start-box":
        return "box"
    if tracker == "projtrack no seed":
        return "none"
    if re.match(r"projtrack [a-z-]+$", tracker):
        return "deepest"
    return None


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def scored(plan_dir, run_dir, truth):
    runs = load_runs(run_dir)
    out = {}
    for (entry, tracker), rows in runs.items():
        k = kind_of(tracker)
        if k is None or not truth.get(entry):
            continue
        m = score(rows, truth[entry])
        m.update(run_stats(rows))
        m["kind"] = k
        out[(entry, tracker)] = m
    return out


def mean(xs):
    xs = [x for x in xs if not math.isnan(x)]
    return statistics.mean(xs) if xs else math.nan


def pct(x):
    return "  n/a" if x is None or math.isnan(x) else f"{100 * x:5.1f}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("plan")
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--json")
    ap.add_argument("--worst", type=int, default=10)
    a = ap.parse_args()
    plan = read_csv(os.path.join(a.plan, "plan.csv"))
    clip_of = {p["entry"]: p["clip"] for p in plan}
    variant = {p["entry"]: p["variant"] for p in plan}
    truth = {e: load_truth(a.plan, e) for e in clip_of}
    before = scored(a.plan, a.before, truth)
    after = scored(a.plan, a.after, truth)
    keys = sorted(set(before) | set(after))
    missing_after = [k for k in keys if k not in after]
    missing_before = [k for k in keys if k not in before]
    both = [k for k in keys if k in before and k in after]
    diff = {k: after[k]["kept"] - before[k]["kept"] for k in both}
    better = [k for k in both if diff[k] > MARGIN]
    worse = [k for k in both if diff[k] < -MARGIN]
    print(f"pairs scored in both: {len(both)}; only before: {len(missing_after)}; "
          f"only after: {len(missing_before)}")
    print(f"better by > 2 points: {len(better)}; worse by > 2 points: {len(worse)}; "
          f"within 2 points: {len(both) - len(better) - len(worse)}")
    print()
    print("mean kept per start kind, % (all entries: clips and variants)  before -> after "
          "[better/worse pairs]")
    for kind in KINDS:
        ks = [k for k in both if before[k]["kind"] == kind]
        print(f"  {kind:8s} n={len(ks):3d}  {pct(mean([before[k]['kept'] for k in ks]))} -> "
              f"{pct(mean([after[k]['kept'] for k in ks]))}  "
              f"[{sum(k in better for k in ks)}/{sum(k in worse for k in ks)}]")
    ks = both
    print(f"  {'all':8s} n={len(ks):3d}  {pct(mean([before[k]['kept'] for k in ks]))} -> "
          f"{pct(mean([after[k]['kept'] for k in ks]))}")
    print()
    print("mean kept per start kind, clips as decoded only (no variant)")
    for kind in KINDS:
        ks = [k for k in both if before[k]["kind"] == kind and not variant[k[0]]]
        print(f"  {kind:8s} n={len(ks):3d}  {pct(mean([before[k]['kept'] for k in ks]))} -> "
              f"{pct(mean([after[k]['kept'] for k in ks]))}")
    print()
    print(f"worst {a.worst} pairs (kept after - before, points):")
    for k in sorted(both, key=lambda k: diff[k])[:a.worst]:
        b, f = before[k], after[k]
        print(f"  {100 * diff[k]:+6.1f}  {k[0]:18s} {k[1]:38s} kept {pct(b['kept'])} -> "
              f"{pct(f['kept'])}  in view {f['in_view']}")
    print()
    print(f"best {a.worst} pairs:")
    for k in sorted(both, key=lambda k: -diff[k])[:a.worst]:
        b, f = before[k], after[k]
        print(f"  {100 * diff[k]:+6.1f}  {k[0]:18s} {k[1]:38s} kept {pct(b['kept'])} -> "
              f"{pct(f['kept'])}")
    print()
    print("per clip (all its entries: clip as decoded and variants): mean kept % before -> "
          "after per start; pairs better/worse")
    print(f"  {'clip':9s} " + "  ".join(f"{k:>15s}" for k in KINDS) + "   better worse  n")
    for clip in CLIPS:
        cells = []
        ks_all = [k for k in both if clip_of[k[0]] == clip]
        for kind in KINDS:
            ks = [k for k in ks_all if before[k]["kind"] == kind]
            cells.append(f"{pct(mean([before[k]['kept'] for k in ks]))}->"
                         f"{pct(mean([after[k]['kept'] for k in ks]))}")
        print(f"  {clip:9s} " + "  ".join(f"{c:>15s}" for c in cells) +
              f"   {sum(k in better for k in ks_all):6d} {sum(k in worse for k in ks_all):5d}"
              f" {len(ks_all):3d}")
    print()
    print("per clip as decoded (no variant): kept % before -> after per start (quarter: mean of 4)")
    for clip in CLIPS:
        cells = []
        for kind in KINDS:
            ks = [k for k in both if k[0] == clip and before[k]["kind"] == kind]
            cells.append(f"{pct(mean([before[k]['kept'] for k in ks]))}->"
                         f"{pct(mean([after[k]['kept'] for k in ks]))}")
        print(f"  {clip:9s} " + "  ".join(f"{c:>15s}" for c in cells))
    print()
    print("no seed: frames reported on a static region (scoring.run_stats 'static'), "
          "measured frames, out-of-view frames reported; before -> after")
    for k in both:
        if before[k]["kind"] != "none" or clip_of[k[0]] not in ("vtest",):
            continue
        b, f = before[k], after[k]
        print(f"  {k[0]:14s} static {b['static']:4d} -> {f['static']:4d}  tracked "
              f"{b['tracked']:4d} -> {f['tracked']:4d}  kept {pct(b['kept'])} -> {pct(f['kept'])}"
              f"  static frames after: {f['static_frames'][:12]}{'...' if len(f['static_frames']) > 12 else ''}")
    tot_b = sum(before[k]["static"] for k in both if before[k]["kind"] == "none")
    tot_a = sum(after[k]["static"] for k in both if after[k]["kind"] == "none")
    print(f"  all no-seed runs: static frames {tot_b} -> {tot_a}")
    if missing_after:
        print("\nnot in the after run:", missing_after[:20])
    if a.json:
        with open(a.json, "w") as f:
            json.dump([{"entry": k[0], "tracker": k[1], "kind": before[k]["kind"],
                        "before": before[k]["kept"], "after": after[k]["kept"],
                        "missed_after": after[k]["missed_frames"],
                        "missed_before": before[k]["missed_frames"]} for k in both], f)


if __name__ == "__main__":
    main()
