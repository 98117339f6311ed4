"""The DAVIS report's pictures: J per sequence beside the published methods (a plot), and a
contact sheet per sequence of projtrack's masks (outlined) against the truth on chosen frames."""
import math
import os
import sys

import cv2
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
from report_kit import plt  # noqa: E402

import results as R  # noqa: E402

PRED_BGR = (255, 0, 255)   # projtrack's mask: magenta
TRUTH_BGR = (0, 220, 0)    # the truth: green
TILE_W = 284               # a tile's width (a third of 854)


def plot_j(res, published, methods, path):
    """J per sequence (and the mean over sequences): projtrack's starts and the baselines as
    markers, the published methods as grey ones."""
    seqs = res.sequences
    xs = np.arange(len(seqs) + 1)
    fig, ax = plt.subplots(figsize=(11, 4.6), dpi=100)
    greys = ["o", "s", "^", "v", "D", "P"]
    for k, m in enumerate(methods):
        ys = [published[m].get(s, math.nan) for s in seqs]
        ys.append(R.mean(ys) if not any(math.isnan(y) for y in ys) else math.nan)
        ax.scatter(xs - 0.18, ys, marker=greys[k % len(greys)], s=22, color="0.6",
                   label=f"{m} (published)", zorder=2)
    styles = {("projtrack", "mask"): ("tab:red", "o"), ("projtrack", "box"): ("tab:blue", "s"),
              ("projtrack", "click"): ("tab:purple", "^"), ("hold", "mask"): ("black", "_"),
              ("CSRT", "box"): ("tab:orange", "x")}
    for key, (colour, marker) in styles.items():
        if key not in res.keys:
            continue
        ys = [100 * res.seq_mean(s, key, "j") for s in seqs] + [100 * res.overall(key, "j")]
        if all(math.isnan(y) for y in ys):
            continue
        ax.scatter(xs + 0.12, ys, marker=marker, s=60 if marker != "_" else 200, color=colour,
                   label=R.LABELS[key], zorder=3, linewidths=2 if marker in "x_" else 1)
    ax.set_xticks(xs)
    ax.set_xticklabels(seqs + ["mean"], rotation=30, ha="right")
    ax.axvline(len(seqs) - 0.5, color="0.8", lw=1)
    ax.set_ylabel("J (region IoU, mean over frames 1..N-2)")
    ax.set_ylim(-2, 102)
    ax.grid(axis="y", color="0.9")
    ax.legend(fontsize=7.5, ncol=2, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.set_title("DAVIS 2016 dev split: J per sequence, projtrack beside the published methods",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def outline(tile, mask, colour):
    contours, _ = cv2.findContours(mask.astype(np.uint8), cv2.RETR_EXTERNAL,
                                   cv2.CHAIN_APPROX_NONE)
    cv2.drawContours(tile, contours, -1, colour, 1, cv2.LINE_AA)


def tile(frame, pred, truth, text):
    """The frame at TILE_W wide with the truth and the prediction outlined, a caption above."""
    h, w = frame.shape[:2]
    size = (TILE_W, round(h * TILE_W / w))
    img = cv2.resize(frame, size, interpolation=cv2.INTER_AREA)
    outline(img, cv2.resize(truth.astype(np.uint8), size, interpolation=cv2.INTER_NEAREST),
            TRUTH_BGR)
    if pred is not None:
        outline(img, cv2.resize(pred.astype(np.uint8), size, interpolation=cv2.INTER_NEAREST),
                PRED_BGR)
    band = np.full((18, size[0], 3), 255, np.uint8)
    cv2.putText(band, text, (3, 13), cv2.FONT_HERSHEY_SIMPLEX, 0.4, (0, 0, 0), 1, cv2.LINE_AA)
    return np.vstack([band, img, np.full((2, size[0], 3), 255, np.uint8)])


def sheet(res, seq, frames, path):
    """A sheet of one sequence (a JPEG: photographs): a row per measured projtrack start, a tile per frame (frames:
    [(index, why)]). Returns False when there is nothing to draw."""
    data = res.meta["data"]
    starts = [k for k in R.LABELS if k[0] == "projtrack" and res.measured(seq, k)]
    if not starts or not frames:
        return False
    rows = []
    for key in starts:
        js = res.per_frame(seq, key, "j")
        tiles = []
        for i, why in frames:
            name = f"{i:05d}"
            frame = cv2.imread(os.path.join(data, "JPEGImages", "480p", seq, name + ".jpg"))
            truth = cv2.imread(os.path.join(data, "Annotations", "480p", seq, name + ".png"),
                               cv2.IMREAD_GRAYSCALE) > 0
            p = os.path.join(res.dir, "masks", seq, f"{key[1]}-{name}.png")
            pred = cv2.imread(p, cv2.IMREAD_GRAYSCALE) > 0 if os.path.exists(p) else None
            j = js.get(i)
            jt = f"J {100 * j:.0f}" if j is not None else "J not measured"
            tiles.append(tile(frame, pred, truth, f"{key[1]}, frame {i} ({why}): {jt}"))
        rows.append(np.hstack(tiles))
    cv2.imwrite(path, np.vstack(rows), [cv2.IMWRITE_JPEG_QUALITY, 90])
    return True
