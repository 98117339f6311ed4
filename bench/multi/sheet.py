"""The several-objects report's contact sheet: the frames run.py kept (sheet/<scene>/), each
object's silhouette from the together run (first-mask start) outlined in its own colour with its
id at its centroid, the truth as a thin white outline; a row per scene, a caption per tile. A PNG
of 256 colours (the photographs' detail is not what it shows)."""
import os

import cv2
import numpy as np
from PIL import Image

# The objects' colours (BGR), by their index in the scene (id = index + 1: added in that order).
COLOURS = [(0, 0, 255), (255, 160, 0), (0, 220, 0), (255, 0, 255), (0, 220, 255),
           (255, 255, 0), (128, 0, 255), (0, 128, 255)]
COLOUR_NAMES = ["red", "blue", "green", "magenta", "yellow", "cyan", "pink", "orange"]
TRUTH = (255, 255, 255)
TILE_W = 320


def outline(img, mask, colour, width):
    contours, _ = cv2.findContours(mask.astype(np.uint8), cv2.RETR_EXTERNAL,
                                   cv2.CHAIN_APPROX_NONE)
    cv2.drawContours(img, contours, -1, colour, width, cv2.LINE_AA)


def label(img, text, at, colour):
    x, y = int(at[0]), int(at[1])
    cv2.putText(img, text, (x - 5, y + 5), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (0, 0, 0), 3,
                cv2.LINE_AA)
    cv2.putText(img, text, (x - 5, y + 5), cv2.FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv2.LINE_AA)


def tile(frame, preds, truths, caption):
    """The frame at TILE_W wide; preds: {index: bool mask or None}; truths: [bool mask]."""
    h, w = frame.shape[:2]
    size = (TILE_W, round(h * TILE_W / w))
    img = cv2.resize(frame, size, interpolation=cv2.INTER_AREA)

    def small(m):
        return cv2.resize(m.astype(np.uint8), size, interpolation=cv2.INTER_NEAREST) > 0
    for t in truths:
        outline(img, small(t), TRUTH, 1)
    for k, m in preds.items():
        if m is None or not m.any():
            continue
        sm = small(m)
        outline(img, sm, COLOURS[k % len(COLOURS)], 2)
        ys, xs = np.nonzero(sm)
        if len(xs):
            label(img, str(k + 1), (xs.mean(), ys.mean()), COLOURS[k % len(COLOURS)])
    band = np.full((16, size[0], 3), 255, np.uint8)
    cv2.putText(band, caption, (3, 12), cv2.FONT_HERSHEY_SIMPLEX, 0.36, (0, 0, 0), 1,
                cv2.LINE_AA)
    return np.vstack([band, img, np.full((2, size[0], 3), 255, np.uint8)])


def read_mask(path):
    return cv2.imread(path, cv2.IMREAD_GRAYSCALE) > 0 if os.path.exists(path) else None


def scene_row(data_dir, scene, caption_of, columns):
    """A row of a scene's kept frames (caption_of(i): frame i's caption); None when run.py kept
    no frame of it."""
    folder = os.path.join(data_dir, "sheet", scene["name"].replace(" ", "_").replace("+", "_"))
    if not os.path.isdir(folder):
        return None
    frames = sorted(int(n[:5]) for n in os.listdir(folder) if n.endswith(".jpg"))
    tiles = []
    for i in frames:
        frame = cv2.imread(os.path.join(folder, f"{i:05d}.jpg"))
        objects = range(len(scene["objects"]))
        preds = {k: read_mask(os.path.join(folder, f"{i:05d}-{k}.png")) for k in objects}
        truths = [read_mask(os.path.join(folder, f"{i:05d}-{k}-truth.png")) for k in objects]
        tiles.append(tile(frame, preds, [t for t in truths if t is not None], caption_of(i)))
    if not tiles:
        return None
    blank = np.full_like(tiles[0], 255)
    tiles += [blank] * (columns - len(tiles))
    return np.hstack(tiles[:columns])


def write(rows, path):
    """The rows (each padded to the widest) stacked, written as a 256-colour PNG."""
    width = max(r.shape[1] for r in rows)
    rows = [np.hstack([r, np.full((r.shape[0], width - r.shape[1], 3), 255, np.uint8)])
            if r.shape[1] < width else r for r in rows]
    img = np.vstack(rows)
    Image.fromarray(img[:, :, ::-1]).quantize(256, dither=Image.Dither.NONE).save(
        path, optimize=True)
