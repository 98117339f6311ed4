#!/usr/bin/python3
"""The several-objects benchmark's driver: scenes composed from a folder in DAVIS layout
(compose.py), every object followed together (one projtrack.MultiTracker; and, to tell the shared
budget's part, one with no work budget: `unlimited`) and alone (projtrack.Tracker) from its first
true mask and from its box, beside OpenCV's CSRT, scored per object on frames 1 .. N-2 (the DAVIS
2016 protocol); then the cost run (timing.py).

    run.py --data DIR --out OUT [--quick] [--mosaics N] [--frames N]

Scenes: mosaics (2×2, sequences at half size, cycled in name order so that each appears
`--mosaics` × 4 / 10 times) and crossings (CROSSINGS: one sequence's object cut out and swept in
front of another's). Writes into OUT:
  frames.csv  one row per run, object and scored frame: J, identity, kept, on the others, visible,
              status, ms (the run's call on that frame: for `together` the one call for all)
  runs.csv    one row per run and object: measured or not (and why), its frames, its start's ms
  cost.csv    the cost run (timing.py)
  sheet/      the frames the contact sheet shows (JPEG), the true masks and the together run's
              masks on them (PNG)
  meta.json   the scenes, the settings, the module, the machine and the run's duration
--quick: one mosaic of 8 frames, one crossing of 16, the cost run on 6 frames.
"""
import argparse
import csv
import json
import os
import platform
import subprocess
import sys
import time

import cv2
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "davis"))
import dataset  # noqa: E402
import results  # noqa: E402

import compose  # noqa: E402
import runs  # noqa: E402
import scoring  # noqa: E402
import timing  # noqa: E402

# (front, back): the front object crosses in front of the back one. Wide, opaque objects in front
# of narrower ones, each sequence once.
CROSSINGS = [("cows", "breakdance"), ("dance-twirl", "camel"), ("goat", "drift-chicane"),
             ("dog", "libby"), ("soapbox", "kite-surf")]
MOSAICS = 5            # 20 tiles: each of davis-dev's ten sequences twice, with other neighbours
QUICK = {"mosaics": 1, "mosaic_frames": 8, "crossings": 1, "crossing_frames": 16,
         "cost_frames": 6}


def sheet_frames(scene, kind):
    """The frames the contact sheet shows: 1, N/3, 2N/3 and N-2 of a mosaic; of a crossing 1, the
    one where the back object shows least, the first where more than half of it shows again and
    N-2."""
    n = len(scene.frames)
    chosen = {1, n // 3, 2 * n // 3, n - 2} if kind == "mosaic" else {1, n - 2}
    if kind == "crossing":
        vis = [compose.visible_share(scene, 1, i) for i in range(n)]
        chosen.add(int(np.nanargmin(vis)))
        span = scoring.hidden_span(vis)
        if span:
            chosen.add(span[1])
    return sorted(i for i in chosen if 1 <= i <= n - 2)


def run_scene(scene, kind, out, rows, run_rows, log):
    """Every run on one scene: together and alone from each start, CSRT per object."""
    n = len(scene.frames)
    last = n - 2
    shown = sheet_frames(scene, kind)
    folder = os.path.join(out, "sheet", safe(scene.name))
    os.makedirs(folder, exist_ok=True)
    for i in shown:
        cv2.imwrite(os.path.join(folder, f"{i:05d}.jpg"), scene.frames[i],
                    [cv2.IMWRITE_JPEG_QUALITY, 92])
        for k, truth in enumerate(scene.truths):
            cv2.imwrite(os.path.join(folder, f"{i:05d}-{k}-truth.png"),
                        truth[i].astype(np.uint8) * 255)
    plan = [("together", s, None) for s in runs.STARTS]
    plan += [("unlimited", s, None) for s in runs.STARTS]
    plan += [("alone", s, k) for s in runs.STARTS for k in range(len(scene.names))]
    plan += [("CSRT", "box", k) for k in range(len(scene.names))]
    for run, start, k in plan:
        objects = range(len(scene.names)) if k is None else [k]
        base = {"scene": scene.name, "kind": kind, "run": run, "start": start}
        try:
            if run == "together":
                gen = runs.together(scene, start, last)
            elif run == "unlimited":
                gen = runs.together(scene, start, last, runs.UNLIMITED)
            elif run == "alone":
                gen = runs.alone(scene, k, start, last)
            else:
                gen = runs.csrt(scene, k, last)
            _, init_ms, _ = next(gen)
        except runs.NotMeasured as e:
            log(f"  {run:8s} {start:4s} {'' if k is None else scene.names[k]}: not measured: {e}")
            for o in objects:
                run_rows.append(dict(base, object=o, name=scene.names[o], measured=0, frames=0,
                                     init_ms="", note=str(e)))
            continue
        js = {o: [] for o in objects}
        failure = []
        for i, ms, preds in runs.guarded(gen, objects, scene.frames[0].shape[:2], last, failure):
            for o, p in preds.items():
                r = scoring.frame_row(scene, o, i, p, box_tracker=(run == "CSRT"))
                js[o].append(float(r["j"]))
                rows.append(dict(base, object=o, name=scene.names[o], frame=i,
                                 ms="" if np.isnan(ms) else f"{ms:.3f}", **r))
                if run == "together" and start == "mask" and i in shown:
                    cv2.imwrite(os.path.join(folder, f"{i:05d}-{o}.png"),
                                p.mask.astype(np.uint8) * 255)
        for o in objects:
            run_rows.append(dict(base, object=o, name=scene.names[o], measured=1,
                                 frames=len(js[o]), init_ms=f"{init_ms:.3f}",
                                 note=failure[0] if failure else ""))
        if failure:
            log(f"  {run:8s} {start:4s} {failure[0]}")
        mean_j = "  ".join(f"{scene.names[o]} {100 * np.mean(js[o]):.1f}" for o in objects)
        log(f"  {run:8s} {start:4s} J {mean_j}")


def safe(name):
    return name.replace(" ", "_").replace("+", "_")


def module_info():
    import projtrack
    t = projtrack.Tracker()
    return {"version": getattr(projtrack, "__version__", ""), "file": projtrack.__file__,
            "multi_tracker": hasattr(projtrack, "MultiTracker"),
            "settings": {k: (v if isinstance(v, (int, float, str, bool)) or v is None else str(v))
                         for k, v in t.settings.items()}}


def source_commit():
    """The repository's commit the run measured ('' outside a git checkout), '+changes' when its
    tracked files differed from it."""
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        head = subprocess.run(["git", "-C", here, "rev-parse", "--short=12", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", here, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""
    return head + (" +changes" if dirty else "")


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else ["scene"])
        w.writeheader()
        w.writerows(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--mosaics", type=int, help=f"2×2 mosaics (default {MOSAICS})")
    ap.add_argument("--frames", type=int, help="at most N frames a mosaic (default: the shortest "
                    "of its sequences)")
    args = ap.parse_args()
    dataset.check_dir(args.data)
    seqs = dataset.sequences(args.data)
    if len(seqs) < 8:
        raise SystemExit(f"multi: {args.data} holds {len(seqs)} sequences; the cost run's 4×2 "
                         "mosaic needs 8")
    q = QUICK if args.quick else {}
    n_mosaics = args.mosaics or q.get("mosaics", MOSAICS)
    mosaic_frames = args.frames or q.get("mosaic_frames")
    crossings = [c for c in CROSSINGS if c[0] in seqs and c[1] in seqs][:q.get("crossings")]
    os.makedirs(args.out, exist_ok=True)
    info = module_info()
    t_start = time.time()
    load_start = os.getloadavg()

    def log(msg):
        print(msg, file=sys.stderr, flush=True)

    rows, run_rows, scenes = [], [], []
    for group in compose.mosaic_groups(seqs, 4, n_mosaics):
        scene = compose.mosaic(args.data, group, 2, 2, mosaic_frames)
        log(f"multi: mosaic {scene.name} ({len(scene.frames)} frames)")
        scenes.append({"name": scene.name, "kind": "mosaic", "objects": scene.names,
                       "frames": len(scene.frames), "tiles": scene.tiles,
                       "size": f"{scene.frames[0].shape[1]}x{scene.frames[0].shape[0]}"})
        run_scene(scene, "mosaic", args.out, rows, run_rows, log)
    for front, back in crossings:
        scene, scale = compose.crossing(args.data, front, back, q.get("crossing_frames"))
        n = len(scene.frames)
        vis = [compose.visible_share(scene, 1, i) for i in range(n)]
        log(f"multi: crossing {scene.name} ({n} frames, front scaled {scale:.2f}, "
            f"least visible {100 * np.nanmin(vis):.0f} %)")
        scenes.append({"name": scene.name, "kind": "crossing", "objects": scene.names,
                       "frames": n, "scale": round(scale, 3),
                       "visible": [round(v, 4) for v in vis],
                       "size": f"{scene.frames[0].shape[1]}x{scene.frames[0].shape[0]}"})
        run_scene(scene, "crossing", args.out, rows, run_rows, log)
    write_csv(os.path.join(args.out, "frames.csv"), rows)
    write_csv(os.path.join(args.out, "runs.csv"), run_rows)
    # the cost run: the eight longest sequences (the longest mosaic), name order within it
    longest = sorted(sorted(seqs, key=lambda s: -len(dataset.frame_names(args.data, s)))[:8])
    cost_scene = compose.mosaic(args.data, longest, 4, 2, q.get("cost_frames"))
    log(f"multi: cost run on {cost_scene.name} ({len(cost_scene.frames)} frames, 4×2)")
    t_cost = time.time()
    cost = timing.run(cost_scene, args.out, log)
    cost["seconds"] = round(time.time() - t_cost, 1)
    meta = {"data": os.path.abspath(args.data), "quick": args.quick, "scenes": scenes,
            "mosaic_frame_limit": mosaic_frames, "cost": cost, "module": info,
            "measured_frames": "1 .. N-2", "opencv": cv2.__version__,
            "opencv_threads": cv2.getNumThreads(), "python": platform.python_version(),
            "commit": source_commit(),
            "machine": results.machine(load_start),
            "date": time.strftime("%Y-%m-%d"), "seconds": round(time.time() - t_start, 1)}
    with open(os.path.join(args.out, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)
    log(f"multi: {len(rows)} scored object-frames and the cost run in {meta['seconds']:.0f} s "
        f"into {args.out}")


if __name__ == "__main__":
    main()
