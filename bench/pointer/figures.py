"""The 3D-mouse benchmark's figures: depth over time with the true and the reported gestures."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from report_kit import plt  # noqa: E402

import scoring  # noqa: E402

COLOURS = {"push": "tab:green", "press": "tab:red", "release": "tab:purple"}


def depth_series(rows, width, height):
    """(times, depth) of the frames the element reported the object on: √(area ÷ frame)."""
    pts = [(r["time"], math.sqrt(r["area"] / (width * height))) for r in rows
           if r["status"] in scoring.TRACKING and r["area"]]
    return ([t for t, _ in pts], [d for _, d in pts]) if pts else ([], [])


def panel(ax, title, rows, width, height, truths=(), with_truth=True):
    t, d = depth_series(rows, width, height)
    ax.plot(t, d, ".-", color="tab:blue", ms=2, lw=0.6, label="depth (element)")
    if with_truth and t:
        ratio = np.median([math.sqrt(r["area"] / r["true_area"]) for r in rows
                           if r["status"] in scoring.TRACKING and r["area"] and r["true_area"]])
        tt = [r["time"] for r in rows]
        ax.plot(tt, [ratio * math.sqrt(r["true_area"] / (width * height)) for r in rows],
                color="0.5", lw=0.8, label="truth (scaled)")
    for e in truths:
        ax.axvline(e["time"], color=COLOURS[e["kind"]], ls="--", lw=1)
    for r in rows:
        if r["gesture"]:
            ax.axvline(r["time"], color=COLOURS.get(r["gesture"], "k"), lw=2.5, alpha=0.5)
    ax.set_title(title, fontsize=9)
    ax.set_ylabel("depth")
    ax.tick_params(labelsize=8)


def draw(seqs, clips, out_dir):
    """Writes the figures into `out_dir`; returns their file names."""
    names = []
    sizes = sorted({s["size"] for s in seqs})
    fig, axes = plt.subplots(len(sizes), 1, figsize=(11, 2.3 * len(sizes)), squeeze=False)
    for ax, size in zip(axes[:, 0], sizes):
        sel = [s for s in seqs if s["size"] == size and s["truths"]]
        best = max(sel, key=lambda s: sum(t["tracked"] for t in s["truths"]), default=None)
        if best is None:
            ax.set_title(f"size {100 * size:.0f} %: not measured", fontsize=9)
            continue
        panel(ax, f"{best['name']}: {best['object']} on {best['background']}, size "
              f"{100 * size:.0f} %, drift ±{100 * best['drift']:.0f} %", best["rows"],
              best["width"], best["height"], best["truths"])
    axes[-1, 0].set_xlabel("s")
    fig.tight_layout()
    names.append("depth-gestures.png")
    fig.savefig(os.path.join(out_dir, names[-1]), dpi=80)
    plt.close(fig)
    fig, axes = plt.subplots(max(len(clips), 1), 1, figsize=(11, 2.0 * max(len(clips), 1)),
                             squeeze=False)
    for ax, c in zip(axes[:, 0], clips):
        w, h = frame_size_of(c)
        panel(ax, f"{c['name']} (no gesture in it)", c["rows"], w, h, with_truth=False)
    axes[-1, 0].set_xlabel("s")
    fig.tight_layout()
    names.append("depth-clips.png")
    fig.savefig(os.path.join(out_dir, names[-1]), dpi=80)
    plt.close(fig)
    return names


def frame_size_of(clip):
    """The clip's frame size as the run recorded it (1×1 when not: depth is then √area)."""
    return clip.get("width") or 1, clip.get("height") or 1
