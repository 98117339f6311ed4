#!/usr/bin/python3
"""The DAVIS benchmark's driver: every tracker of runners.plan() on every sequence of a folder in
DAVIS layout, scored per frame over frames 1 .. N-2 (the DAVIS 2016 protocol).

    run.py --data DIR --out OUT [--quick] [--sequences a,b] [--frames N] [--model NAME]
           [--trackers projtrack,hold,...]

Writes into OUT:
  frames.csv  one row per run and scored frame: J, F (with its precision and recall), kept, ms
  runs.csv    one row per run: measured or not (and why), its frames, its start's cost
  masks/      the predicted masks (PNG) of projtrack's runs on the frames the contact sheets show:
              1, N/2, N-2 and the lowest J of the first-mask start (save_masks)
  meta.json   the data, the settings, the module, the machine and the run's duration
--quick: two sequences (--sequences, default cows and dog), 10 frames each (--frames).
"""
import argparse
import csv
import json
import math
import os
import platform
import sys
import time

import cv2
import numpy as np

import dataset
import measures
import results
import runners

QUICK_SEQUENCES = ["cows", "dog"]
QUICK_FRAMES = 10


def sheet_frames(n, js):
    """The frames a contact sheet shows for a run over a sequence of n frames whose J per scored
    frame is js ({frame: J}): 1, N/2, N-2 and the one with the lowest J."""
    chosen = {1, n // 2, n - 2}
    if js:
        chosen.add(min(js, key=lambda i: (js[i], i)))
    return sorted(i for i in chosen if 1 <= i <= n - 2)


def run_one(seq, tracker, start, frames, masks, args, rows):
    """One run, scored; its frames' rows appended to rows. Returns its runs.csv row, its J per
    scored frame ({frame: J}) and, for projtrack, its predicted masks ({frame: packed bits})."""
    n = len(frames)
    last = n - 2  # frame N-1 is not scored: no need to track it
    base = {"sequence": seq, "tracker": tracker, "start": start}
    try:
        gen = runners.runner(tracker, start, frames, masks[0], last, args.model)
    except runners.NotMeasured as e:
        print(f"  {tracker:10s} {start:5s} not measured: {e}", file=sys.stderr)
        return dict(base, measured=0, frames=0, init_ms="", note=str(e)), {}, {}
    _, init_ms = next(gen)
    js, kept_masks = {}, {}
    for i, p in gen:
        truth = masks[i]
        j = measures.region_j(p.mask, truth)
        f, prec, rec = measures.boundary_f(p.mask, truth)
        tc, ta = measures.centroid_area(truth)
        if tracker in runners.OPENCV:
            # a box tracker's kept: its box against the true box
            tc, ta = measures.box_centroid_area(dataset.bbox(truth))
        k = measures.kept(p.centroid, p.area, tc, ta)
        js[i] = j
        if tracker == "projtrack":
            kept_masks[i] = np.packbits(p.mask)
        rows.append(dict(base, frame=i, j=f"{j:.5f}", f=f"{f:.5f}", precision=f"{prec:.5f}",
                         recall=f"{rec:.5f}", kept=int(k),
                         ms="" if math.isnan(p.ms) else f"{p.ms:.3f}",
                         pred_area=f"{p.area:.0f}", true_area=int(np.count_nonzero(truth)),
                         status=p.status))
    mean_j = sum(js.values()) / len(js) if js else math.nan
    print(f"  {tracker:10s} {start:5s} J {100 * mean_j:5.1f} over {len(js)} frames",
          file=sys.stderr)
    return dict(base, measured=1, frames=len(js),
                init_ms="" if math.isnan(init_ms) else f"{init_ms:.3f}", note=""), js, kept_masks


def save_masks(out, seq, n, shape, js, packed):
    """The predicted masks of projtrack's runs on the frames the sequence's contact sheet shows:
    1, N/2, N-2 and the lowest J of the first-mask start (of the box start when the mask start
    was not measured). js and packed: {start: {frame: ...}}."""
    sheet_start = "mask" if js.get("mask") else "box"
    frames = sheet_frames(n, js.get(sheet_start, {}))
    folder = os.path.join(out, "masks", seq)
    os.makedirs(folder, exist_ok=True)
    for start, masks in packed.items():
        for i in frames:
            m = np.unpackbits(masks[i])[:shape[0] * shape[1]].reshape(shape)
            cv2.imwrite(os.path.join(folder, f"{start}-{i:05d}.png"), m * 255)


def module_info(model):
    import projtrack
    t = runners.make_projtrack(model)
    return {"version": getattr(projtrack, "__version__", ""), "file": projtrack.__file__,
            "settings": {k: (v if isinstance(v, (int, float, str, bool)) or v is None else str(v))
                         for k, v in t.settings.items()}}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--sequences", help="comma-separated (default: all; --quick: cows,dog)")
    ap.add_argument("--frames", type=int, help="the first N frames of each sequence")
    ap.add_argument("--model", help="projtrack's object model (default: the module's)")
    ap.add_argument("--trackers", help="comma-separated trackers to run (default: all): "
                    + ",".join(dict.fromkeys(t for t, _ in runners.plan())))
    args = ap.parse_args()
    dataset.check_dir(args.data)
    seqs = dataset.sequences(args.data)
    wanted = args.sequences.split(",") if args.sequences else (
        QUICK_SEQUENCES if args.quick else seqs)
    unknown = [s for s in wanted if s not in seqs]
    if unknown:
        raise SystemExit(f"davis: no sequence {', '.join(unknown)} in {args.data}")
    limit = args.frames or (QUICK_FRAMES if args.quick else None)
    names = dict.fromkeys(t for t, _ in runners.plan())
    only = args.trackers.split(",") if args.trackers else list(names)
    if any(t not in names for t in only):
        raise SystemExit(f"davis: --trackers: not among {', '.join(names)}")
    try:
        info = module_info(args.model)
    except ValueError as e:
        raise SystemExit(f"davis: projtrack.Tracker(model={args.model!r}): {e}")
    os.makedirs(args.out, exist_ok=True)
    t_start = time.time()
    load_start = os.getloadavg()
    rows, runs, lengths, sizes = [], [], {}, {}
    for seq in wanted:
        frames, masks = dataset.load(args.data, seq, limit)
        lengths[seq] = len(frames)
        sizes[seq] = f"{frames[0].shape[1]}x{frames[0].shape[0]}"
        print(f"davis: {seq} ({len(frames)} frames)", file=sys.stderr)
        js, packed = {}, {}
        for tracker, start in [r for r in runners.plan() if r[0] in only]:
            run, js_run, packed_run = run_one(seq, tracker, start, frames, masks, args, rows)
            runs.append(run)
            if tracker == "projtrack" and run["measured"]:
                js[start], packed[start] = js_run, packed_run
        save_masks(args.out, seq, len(frames), masks[0].shape, js, packed)
    write_csv(os.path.join(args.out, "frames.csv"), rows)
    write_csv(os.path.join(args.out, "runs.csv"), runs)
    meta = {"data": os.path.abspath(args.data), "sequences": wanted, "frames": lengths, "sizes": sizes,
            "frame_limit": limit, "quick": args.quick, "trackers": only,
            "opencv_threads": cv2.getNumThreads(), "model": args.model or "",
            "module": info, "opencv": cv2.__version__, "python": platform.python_version(),
            "machine": results.machine(load_start),
            "date": time.strftime("%Y-%m-%d"), "seconds": round(time.time() - t_start, 1)}
    with open(os.path.join(args.out, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)
    print(f"davis: {len(rows)} scored frames in {meta['seconds']:.0f} s into {args.out}",
          file=sys.stderr)


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else ["sequence"])
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
