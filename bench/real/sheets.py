"""Contact sheets of the frames a run misses: the element's own overlay (draw=true, re-run by
`projtrack-real --render` from the requests this module writes) or, for a run without one, the
decoded frame with what the run reported drawn over it; the true silhouette in green. Small
objects are shown in a crop around the true box, enlarged."""
import csv
import os

import numpy as np

from scoring import area_ratio, centroid_error, miss_category

try:
    import cv2
except ImportError:  # sheets need python3-opencv; the tables do not
    cv2 = None

TILES = 8            # missed frames a sheet shows, spread over the misses
TILE_W = 240         # a tile's width (its height follows the frame's shape)
SMALL = 1 / 8        # an object whose box's longer side is under this share of the frame's
ZOOM_SIDES = 6       # is shown in a crop this many times its longer side wide


def slug(name):
    return name.replace("projtrack ", "").replace(" ", "-").replace(",", "-")


def pick_frames(missed, count=TILES):
    """Up to `count` frames spread over the missed ones."""
    if len(missed) <= count:
        return list(missed)
    return [missed[round(i * (len(missed) - 1) / (count - 1))] for i in range(count)]


def write_requests(path, sheets):
    """sheets: [(entry, tracker, props, frames)]; props None for a run without an overlay."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["entry", "slug", "props", "frames"])
        for entry, tracker, props, frames in sheets:
            w.writerow([entry, slug(tracker), props or "", " ".join(map(str, frames))])


def caption(i, r, t):
    if r is None:
        return f"{i}: no row"
    if not r["measured"]:
        return f"{i}: {r['status']}"
    c = miss_category(r, t) or "kept"
    return f"{i}: {c}, area {area_ratio(r, t):.2f}x, off {centroid_error(r, t):.0f} px"


def draw_truth(img, outlines, t):
    for kind, pts in outlines:
        cv2.polylines(img, [pts], True, (0, 255, 0) if kind == "outer" else (0, 160, 0), 1)
    if t and t["area"]:
        radius = int(max(1, min(4, t["area"] ** 0.5 / 10)))
        cv2.circle(img, (round(t["centroid_x"]), round(t["centroid_y"])), radius, (0, 255, 0), -1)


def draw_report(img, r):
    if r and r["measured"]:
        cv2.rectangle(img, (r["x"], r["y"]), (r["x"] + r["width"] - 1, r["y"] + r["height"] - 1),
                      (0, 0, 255), 1)
        cv2.drawMarker(img, (round(r["centroid_x"]), round(r["centroid_y"])), (0, 0, 255),
                       cv2.MARKER_CROSS, 12, 2)


def zoom(img, t):
    """A crop around a small object's true box, enlarged; the frame itself otherwise."""
    h, w = img.shape[:2]
    if not t or not t["area"] or max(t["width"], t["height"]) >= SMALL * max(w, h):
        return img
    side = int(min(max(w, h), max(80, ZOOM_SIDES * max(t["width"], t["height"]))))
    cx, cy = int(t["centroid_x"]), int(t["centroid_y"])
    x0 = int(np.clip(cx - side // 2, 0, max(0, w - side)))
    y0 = int(np.clip(cy - side * h // w // 2, 0, max(0, h - side * h // w)))
    return img[y0:y0 + max(1, side * h // w), x0:x0 + side]


def tile(img, text):
    """The image at TILE_W wide with the caption in a band below it (the element's overlay
    writes its status at the top)."""
    img = cv2.resize(img, (TILE_W, max(1, round(TILE_W * img.shape[0] / img.shape[1]))),
                     interpolation=cv2.INTER_NEAREST)
    img = cv2.copyMakeBorder(img, 0, 18, 0, 0, cv2.BORDER_CONSTANT, value=(0, 0, 0))
    cv2.putText(img, text, (4, img.shape[0] - 5), cv2.FONT_HERSHEY_SIMPLEX, 0.34,
                (255, 255, 255), 1)
    return img


def contact_sheet(frames_dir, rows, truth, outlines, frames, path, overlay):
    """Writes the sheet; False when a frame to draw on is missing (or without OpenCV)."""
    if cv2 is None or not frames:
        return False
    by = {r["frame"]: r for r in rows}
    tiles = []
    for i in frames:
        p = os.path.join(frames_dir, f"{i:03d}.jpg")
        img = cv2.imread(p) if os.path.exists(p) else None
        if img is None:
            return False
        r, t = by.get(i), truth[i]
        draw_truth(img, outlines.get(i, []), t)
        if not overlay:
            draw_report(img, r)
        tiles.append(tile(zoom(img, t), caption(i, r, t)))
    h = max(t.shape[0] for t in tiles)
    tiles = [cv2.copyMakeBorder(t, 0, h - t.shape[0], 0, 0, cv2.BORDER_CONSTANT) for t in tiles]
    cols = 4
    while len(tiles) % cols:
        tiles.append(np.zeros_like(tiles[0]))
    sheet = np.vstack([np.hstack(tiles[k:k + cols]) for k in range(0, len(tiles), cols)])
    os.makedirs(os.path.dirname(path), exist_ok=True)
    cv2.imwrite(path, sheet, [cv2.IMWRITE_JPEG_QUALITY, 75])
    return True
