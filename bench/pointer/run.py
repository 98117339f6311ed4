#!/usr/bin/python3
"""The 3D-mouse benchmark's driver: every scripted sequence (script.py, rendered by scene.py) and
every real clip that holds no gesture through the projtrack element with its default settings,
frame by frame; writes what the element reported and the truth beside it.

    run.py --out DIR [--quick] [--clips-dir DIR]

DIR receives frames.csv (one row per frame: the truth for the sequences, the element's message),
truth.csv (the gestures the sequences hold), meta.json (the run's settings and sequences).
Needs the plugin on GST_PLUGIN_PATH; the clips are opencv-doc's (cup.mp4.gz and box.mp4.gz are
unpacked into --clips-dir, default DIR/clips).
"""
import argparse
import csv
import gzip
import json
import os
import platform
import shutil
import sys
import time

import gi
import numpy as np

gi.require_version("Gst", "1.0")
from gi.repository import Gst  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scene  # noqa: E402
import script  # noqa: E402

DOC = "/usr/share/doc/opencv-doc"
# The real clips that hold no gesture: a hand turning a cup, a box; people walking; a cartoon
# with shot cuts.
CLIPS = {"cup": f"{DOC}/opencv4/html/cup.mp4.gz", "box": f"{DOC}/opencv4/html/box.mp4.gz",
         "vtest": f"{DOC}/examples/data/vtest.avi", "Megamind": f"{DOC}/examples/data/Megamind.avi"}
QUICK_CLIP_FRAMES = 40
FIELDS = ["source", "name", "frame", "time", "true_scale", "true_area", "true_x", "true_y",
          "status", "area", "depth", "position_x", "position_y", "x", "y", "width", "height",
          "gesture", "acquired", "track"]


def message_row(s):
    """The fields of one projtrack message the benchmark keeps (empty when absent)."""
    def get(name):
        ok, v = (s.get_double(name) if name in ("area", "depth", "position-x", "position-y")
                 else s.get_int(name))
        return v if ok else ""
    row = {k.replace("-", "_"): get(k) for k in ("area", "depth", "position-x", "position-y",
                                                 "x", "y", "width", "height")}
    row["status"] = s.get_string("status") or ""
    row["gesture"] = s.get_string("gesture") or ""
    row["acquired"] = int(s.has_field("acquired"))
    ok, track = s.get_uint("track-id") if s.has_field("track-id") else (False, 0)
    row["track"] = track if ok else ""
    return row


def take_messages(bus):
    """The projtrack element messages waiting on `bus`; raises on an error message."""
    out = []
    while True:
        msg = bus.pop_filtered(Gst.MessageType.ELEMENT | Gst.MessageType.ERROR)
        if msg is None:
            return out
        if msg.type == Gst.MessageType.ERROR:
            raise RuntimeError(msg.parse_error()[0].message)
        if msg.get_structure().get_name() == "projtrack":
            out.append(msg.get_structure())


def run_sequence(seq, writer):
    """Renders `seq` frame by frame into the element (appsrc → videoconvert to I420, as a
    decoder or camera gives it → projtrack → appsink); one row per frame. The element starts
    from the object's box on the first frame (start-box, as a user shows it the object) and
    otherwise runs with its default settings."""
    x, y, w, h = scene.object_box(seq, 0.0)
    pipeline = Gst.parse_launch(
        f"appsrc name=src format=time caps=video/x-raw,format=BGR,width={seq.width},"
        f"height={seq.height},framerate={seq.fps}/1 ! videoconvert ! video/x-raw,format=I420 ! "
        f'projtrack start-box="<{x},{y},{w},{h}>" ! appsink name=sink sync=false')
    src, sink, bus = pipeline.get_by_name("src"), pipeline.get_by_name("sink"), pipeline.get_bus()
    pipeline.set_state(Gst.State.PLAYING)
    rng = np.random.default_rng(seq.seed)
    noise = scene.NoiseBank(seq.noise, seq.width, seq.height, rng)
    try:
        for i in range(seq.frames()):
            buf = Gst.Buffer.new_wrapped(scene.render(seq, i, noise, rng).tobytes())
            buf.pts, buf.duration = i * Gst.SECOND // seq.fps, Gst.SECOND // seq.fps
            if src.emit("push-buffer", buf) != Gst.FlowReturn.OK or sink.emit("pull-sample") is None:
                raise RuntimeError(f"{seq.name}: the pipeline stopped at frame {i}")
            t = i / seq.fps
            pose = seq.pose(t)
            row = {"source": "sequence", "name": seq.name, "frame": i, "time": f"{t:.4f}",
                   "true_scale": f"{pose.scale:.5f}", "true_area": f"{scene.object_area(seq, t):.1f}",
                   "true_x": f"{pose.x:.1f}", "true_y": f"{pose.y:.1f}"}
            for s in take_messages(bus)[-1:]:
                row.update(message_row(s))
            writer.writerow(row)
    finally:
        pipeline.set_state(Gst.State.NULL)


def run_clip(name, path, frames, writer):
    """A real clip decoded and converted as any application would, through projtrack with its
    default settings; one row per message (one per frame)."""
    pipeline = Gst.parse_launch(f'filesrc location="{path}" ! decodebin ! videoconvert ! '
                                'projtrack name=pt ! fakesink sync=false')
    bus = pipeline.get_bus()
    pipeline.set_state(Gst.State.PLAYING)
    n, size = 0, {}
    try:
        while frames is None or n < frames:
            msg = bus.timed_pop_filtered(60 * Gst.SECOND, Gst.MessageType.ELEMENT |
                                         Gst.MessageType.ERROR | Gst.MessageType.EOS)
            if msg is None:
                raise RuntimeError(f"{name}: no message for a minute")
            if msg.type == Gst.MessageType.EOS:
                break
            if msg.type == Gst.MessageType.ERROR:
                raise RuntimeError(f"{name}: {msg.parse_error()[0].message}")
            s = msg.get_structure()
            if s.get_name() != "projtrack":
                continue
            ok, pts = s.get_uint64("timestamp")
            row = {"source": "clip", "name": name, "frame": n,
                   "time": f"{pts / Gst.SECOND:.4f}" if ok else ""}
            row.update(message_row(s))
            writer.writerow(row)
            n += 1
            if not size:
                caps = pipeline.get_by_name("pt").get_static_pad("sink").get_current_caps()
                st = caps.get_structure(0)
                size = {"width": st.get_int("width")[1], "height": st.get_int("height")[1]}
    finally:
        pipeline.set_state(Gst.State.NULL)
    return n, size


def clip_paths(clips_dir):
    """Each clip's playable path: the gzipped ones unpacked into `clips_dir`."""
    os.makedirs(clips_dir, exist_ok=True)
    out = {}
    for name, path in CLIPS.items():
        if path.endswith(".gz"):
            target = os.path.join(clips_dir, os.path.basename(path)[:-3])
            if not os.path.exists(target):
                with gzip.open(path) as src, open(target, "wb") as dst:
                    shutil.copyfileobj(src, dst)
            path = target
        out[name] = path
    return out


def write_truth(seqs, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["name", "gesture", "kind", "time", "frame", "depth", "duration", "hold",
                    "start", "end"])
        for seq in seqs:
            for kind, t, i in seq.truths():
                g = seq.gestures[i]
                w.writerow([seq.name, i, kind, f"{t:.4f}", round(t * seq.fps), f"{g.depth:.4f}",
                            f"{g.rise + g.fall:.4f}", f"{g.hold:.4f}", f"{g.start:.4f}",
                            f"{g.end:.4f}"])


def describe(seq):
    return {"name": seq.name, "object": seq.object, "background": seq.background,
            "size": seq.size, "drift": seq.drift, "drift_period": round(seq.drift_period, 3),
            "noise": seq.noise, "frames": seq.frames(), "fps": seq.fps,
            "width": seq.width, "height": seq.height, "gestures": len(seq.gestures)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true", help="a smoke run: short sequences, "
                    f"the first {QUICK_CLIP_FRAMES} frames of each clip")
    ap.add_argument("--clips-dir")
    ap.add_argument("--seed", type=int, default=script.SEED,
                    help="the scripts' random seed (the documented run uses the default)")
    ap.add_argument("--no-clips", action="store_true", help="the sequences only")
    args = ap.parse_args()
    Gst.init(None)
    if Gst.ElementFactory.find("projtrack") is None:
        sys.exit("run.py: no projtrack element: set GST_PLUGIN_PATH to the build's gst/ folder")
    os.makedirs(args.out, exist_ok=True)
    seqs = script.quick_sequences() if args.quick else \
        script.gesture_sequences(args.seed) + script.idle_sequences(args.seed)
    clip_frames = QUICK_CLIP_FRAMES if args.quick else None
    write_truth(seqs, os.path.join(args.out, "truth.csv"))
    started = time.time()
    clips = {}
    with open(os.path.join(args.out, "frames.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, FIELDS)
        writer.writeheader()
        for k, seq in enumerate(seqs):
            print(f"run.py: sequence {k + 1}/{len(seqs)} {seq.name}", file=sys.stderr)
            run_sequence(seq, writer)
        paths = {} if args.no_clips else clip_paths(args.clips_dir or os.path.join(args.out, "clips"))
        for name, path in paths.items():
            print(f"run.py: clip {name}", file=sys.stderr)
            n, size = run_clip(name, path, clip_frames, writer)
            clips[name] = dict({"path": CLIPS[name], "frames": n}, **size)
    meta = {"quick": args.quick, "sequences": [describe(s) for s in seqs], "clips": clips,
            "element": "projtrack (default settings)", "input": "I420 via videoconvert",
            "gstreamer": Gst.version_string(), "machine": platform.machine(),
            "seconds": round(time.time() - started, 1)}
    with open(os.path.join(args.out, "meta.json"), "w") as f:
        json.dump(meta, f, indent=1)


if __name__ == "__main__":
    main()
