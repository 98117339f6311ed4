#!/usr/bin/python3
"""The plan of a real-footage run: for every clip of the set (clip_set.py) found, and each of its
variants, which frames projtrack-real decodes and how it changes them, the truth of what it will
show, and where each run starts.

    prepare.py ROOT TRUTH_DIR DATA_DIR [--frames N] [--only CLIP,...] [--entries E,...]

ROOT: where the packages were unpacked (clip_set.resolve). Writes DATA_DIR/plan.csv (one row a
clip or variant: source, kind, first frame, step, mirror, crop, scale, lighting), DATA_DIR/seeds.csv
(entry, kind, x, y, w, h: the deepest point, quarter points and true box of the entry's first
frame), DATA_DIR/truth/<entry>.csv and _outlines.csv.gz (renumbered from the entry's first frame,
moved as the variant moves the frame) and DATA_DIR/clips.csv (each clip's motion measure).

A clip whose object comes into view after frame 0 starts at its first in-view frame; a clip
without labels runs from frame 0 without a seed. With --frames N, N frames an entry (smoke runs);
with --entries, only those clips and variants (e.g. cup,ellipse-edge: a test's segments).
"""
import argparse
import csv
import gzip
import os
import shutil
import sys

# FFmpeg's complaints about the clips' H.264 (harmless: the labels were made on the same decoded
# frames) would drown the run's output.
os.environ.setdefault("OPENCV_FFMPEG_LOGLEVEL", "-8")
import cv2  # noqa: E402

import clip_set  # noqa: E402
import truth_geometry as tg  # noqa: E402
from motion import one_mover  # noqa: E402
from seeds import seeds  # noqa: E402

PLAN = ["entry", "clip", "variant", "source", "kind", "start", "frames", "step", "mirror",
        "crop_x", "crop_y", "crop_w", "crop_h", "scale", "lighting"]
FAST_STEP = 3  # projtrack-real's kFastStep: the fast variant keeps one frame in 3


def frame_size(clip, source):
    if clip.kind == "pgm":
        img = cv2.imread(clip_set.pgm_files(source)[0], cv2.IMREAD_UNCHANGED)
        return img.shape[1], img.shape[0]
    cap = cv2.VideoCapture(source)
    size = int(cap.get(cv2.CAP_PROP_FRAME_WIDTH)), int(cap.get(cv2.CAP_PROP_FRAME_HEIGHT))
    cap.release()
    return size


def edge_crop(row, size):
    """The crop that puts the nearest frame edge EDGE_CUT of the way into the object's box."""
    w, h = size
    x, y, bw, bh = (int(row[k]) for k in ("x", "y", "width", "height"))
    gaps = {"left": x, "right": w - x - bw, "top": y, "bottom": h - y - bh}
    side = min(gaps, key=gaps.get)
    cut_w, cut_h = round(clip_set.EDGE_CUT * bw), round(clip_set.EDGE_CUT * bh)
    if side == "left":
        return (x + cut_w, 0, w - x - cut_w, h), side
    if side == "right":
        return (0, 0, x + bw - cut_w, h), side
    if side == "top":
        return (0, y + cut_h, w, h - y - cut_h), side
    return (0, 0, w, y + bh - cut_h), side


def entry_truth(rows, outlines, size, start, step, geometry):
    """The truth rows and outlines of an entry, renumbered from its first frame."""
    out_rows, out_lines, masks = [], {}, []
    for k, i in enumerate(range(start, len(rows), step)):
        r = rows[i]
        if not geometry and not tg.in_view(r):
            out_rows.append(tg.fmt_row(r, k))
            masks.append(None)
            continue
        mask = tg.rasterise(outlines.get(i, []), size)
        if geometry:
            mask = tg.transform(mask, **geometry)
            out_rows.append(tg.row_of(mask, k, f"{r['luma_mean']:.2f}"))
            out_lines[k] = tg.outlines_of(mask)
        else:
            out_rows.append(tg.fmt_row(r, k))
            out_lines[k] = outlines.get(i, [])
        masks.append(mask)
    return out_rows, out_lines, masks


def plan_clip(clip, source, truth_dir, data, args, plan, seed_rows, clip_rows):
    size = frame_size(clip, source)
    truth_path = os.path.join(truth_dir, clip.name + ".csv")
    if not os.path.exists(truth_path):
        plan.append([clip.name, clip.name, "", source, clip.kind, 0, args.frames or 0, 1, 0,
                     0, 0, size[0], size[1], 1, ""])
        return
    rows = tg.read_truth(truth_path)
    outlines = tg.read_outlines(os.path.join(truth_dir, clip.name + "_outlines.csv.gz"))
    start = next((i for i, r in enumerate(rows) if tg.in_view(r)), None)
    if start is None:
        print(f"prepare: {clip.name}: the object is never in view", file=sys.stderr)
        return
    if args.frames:
        rows = rows[:start + args.frames]
    first = rows[start]
    crop, side = edge_crop(first, size)
    variants = clip_set.variants_for(len(rows) - start)
    clip_rows.append([clip.name, start, len(rows) - start, side,
                      f"{one_mover(clip, source, rows, start):.3f}" if not args.frames else ""])
    for variant in [""] + variants:
        entry = clip.name + (f"-{variant}" if variant else "")
        if args.entries and entry not in args.entries.split(","):
            continue
        step = FAST_STEP if variant == "fast" else 1
        geometry = {"edge": dict(crop=crop), "half": dict(scale=0.5),
                    "mirror": dict(mirror=True)}.get(variant)
        t_rows, t_lines, masks = entry_truth(rows, outlines, size, start, step, geometry)
        tg.write_truth(os.path.join(data, "truth", entry), t_rows, t_lines)
        c = crop if variant == "edge" else (0, 0) + size
        lighting = "" if variant in clip_set.GEOMETRIC else variant
        plan.append([entry, clip.name, variant, source, clip.kind, start, len(t_rows), step,
                     int(variant == "mirror"), *c, 0.5 if variant == "half" else 1, lighting])
        mask = masks[0]
        if variant == "" and mask is not None:  # the labels' own deepest point and box
            mask = tg.rasterise(outlines.get(start, []), size)
        for kind, x, y, w, h in seeds(mask):
            if variant == "" and kind == "deepest":
                x, y = int(first["inner_x"]), int(first["inner_y"])
            if variant == "" and kind == "box":
                x, y, w, h = (int(first[k]) for k in ("x", "y", "width", "height"))
            seed_rows.append([entry, kind, x, y, w, h])


def unpack(clip, source, data):
    """A gzipped clip unpacked once into DATA/clips."""
    if clip.kind != "video.gz":
        return source
    out = os.path.join(data, "clips", clip.name + ".mp4")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with gzip.open(source) as src, open(out, "wb") as dst:
        shutil.copyfileobj(src, dst)
    return out


def write(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("root")
    ap.add_argument("truth_dir")
    ap.add_argument("data")
    ap.add_argument("--frames", type=int, default=0)
    ap.add_argument("--only")
    ap.add_argument("--entries")
    args = ap.parse_args()
    os.makedirs(os.path.join(args.data, "truth"), exist_ok=True)
    wanted = args.only.split(",") if args.only else [c.name for c in clip_set.CLIPS]
    if args.entries:
        wanted = [c for c in wanted if any(e.split("-")[0] == c for e in args.entries.split(","))]
    plan, seed_rows, clip_rows = [], [], []
    for name in wanted:
        clip = clip_set.BY_NAME[name]
        source = clip_set.resolve(clip, args.root)
        if source is None:
            print(f"prepare: {clip.name}: {clip.path} not found ({clip.package})", file=sys.stderr)
            continue
        source = unpack(clip, source, args.data)
        plan_clip(clip, source, args.truth_dir, args.data, args, plan, seed_rows, clip_rows)
    write(os.path.join(args.data, "plan.csv"), PLAN, plan)
    write(os.path.join(args.data, "seeds.csv"), ["entry", "kind", "x", "y", "w", "h"], seed_rows)
    write(os.path.join(args.data, "clips.csv"),
          ["clip", "start", "frames", "edge_side", "outside_motion"], clip_rows)


if __name__ == "__main__":
    main()
