#!/usr/bin/python3
"""Ground truth for the real clips of opencv-doc: the held object's silhouette on every frame,
made by colour segmentation alone, never from projtrack's output.

    bench/real/label_truth.py CLIPS_DIR OUT_DIR [--sheets DIR]

CLIPS_DIR holds cup.mp4 and box.mp4 (gunzipped from /usr/share/doc/opencv-doc/opencv4/html/).
Writes OUT_DIR/<clip>.csv (per frame: centroid, area, bounding box, the silhouette's point
farthest from its border, mean luma for checking that a decoder gives the same frames) and
OUT_DIR/<clip>_outlines.csv.gz (the silhouette's outer and hole contours, simplified to within
one pixel). With --sheets, contact sheets of every frame with the silhouette drawn, for checking
by eye. bench/real/truth/README.md says how the rules were checked and their known errors.
"""
import argparse
import csv
import gzip
import os

import cv2
import numpy as np

from truth_geometry import disc, farthest_inside, fill_holes
from truth_geometry import outlines_of as outlines


def main_components(mask, near, min_share):
    """The largest component and those of at least min_share of its area within `near` px of
    its box (a thumb across the object cuts it in two)."""
    n, labels, stats, _ = cv2.connectedComponentsWithStats(mask, connectivity=8)
    if n < 2:
        return np.zeros_like(mask)
    big = 1 + int(np.argmax(stats[1:, cv2.CC_STAT_AREA]))
    bx, by, bw, bh, ba = stats[big]
    keep = np.zeros_like(mask)
    for i in range(1, n):
        x, y, w, h, a = stats[i]
        if (a >= min_share * ba and x < bx + bw + near and x + w > bx - near and
                y < by + bh + near and y + h > by - near):
            keep[labels == i] = 1
    return keep


def cup_silhouette(bgr):
    """The dark cup on a white wall, without the fingers in front of it.

    Skin is told by its red chroma (Cr > 134: the cup's is 126-132, the hand's 137-170 even in
    the shadow under it). The cup is the dark (V < 100) pixels that are not skin, as the main
    components; its prints and highlights are filled as holes, and a 15 px closing fills
    highlights that reach its rim. Then the fingers in front are cut out: skin that is bright
    (V >= 90). Fingertips seen through the dark translucent plastic are darker and stay in.
    """
    ycc = cv2.cvtColor(bgr, cv2.COLOR_BGR2YCrCb)
    v = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)[..., 2]
    skin = cv2.morphologyEx((ycc[..., 1] > 134).astype(np.uint8), cv2.MORPH_OPEN, disc(3))
    dark = ((v < 100) & (skin == 0)).astype(np.uint8)
    dark = cv2.morphologyEx(dark, cv2.MORPH_OPEN, disc(5))  # the shadow lines along the arm
    keep = main_components(dark, near=15, min_share=0.01)
    keep = cv2.morphologyEx(keep, cv2.MORPH_CLOSE, disc(9))
    cup = fill_holes(cv2.morphologyEx(fill_holes(keep), cv2.MORPH_CLOSE, disc(15)))
    return cup & ~((skin > 0) & (v >= 90)).astype(np.uint8)


def box_silhouette(bgr):
    """The printed yellow box: the convex hull of its yellow print (a box projects convex).

    Yellow is told by its low blue chroma (Cb < 108; the tablecloth, the wall, the hand and the
    wooden floor are above 112) with some light (Y > 60). The hull takes in the pictures printed
    on the box, which are not yellow.
    """
    ycc = cv2.cvtColor(bgr, cv2.COLOR_BGR2YCrCb)
    yellow = ((ycc[..., 2] < 108) & (ycc[..., 0] > 60)).astype(np.uint8)
    yellow = cv2.morphologyEx(yellow, cv2.MORPH_OPEN, disc(5))
    keep = main_components(yellow, near=0, min_share=0.01)
    points = cv2.findNonZero(keep)
    box = np.zeros_like(yellow)
    if points is not None:
        cv2.fillConvexPoly(box, cv2.convexHull(points), 1)
    return box


SILHOUETTES = {'cup': cup_silhouette, 'box': box_silhouette}


def frames_of(path):
    cap = cv2.VideoCapture(path)
    if not cap.isOpened():
        raise SystemExit(f'label_truth: cannot read {path}')
    while True:
        ok, frame = cap.read()
        if not ok:
            return
        yield frame


def sheet(frames, masks, first, step, path):
    tiles = []
    for i in range(0, len(frames), step):
        f = frames[i].copy()
        m = masks[i].astype(bool)
        f[m] = (0.6 * f[m] + 0.4 * np.array([255, 0, 255])).astype(np.uint8)
        cv2.putText(f, str(first + i), (10, 30), cv2.FONT_HERSHEY_SIMPLEX, 1, (255, 0, 0), 2)
        tiles.append(cv2.resize(f, None, fx=0.5, fy=0.5))
    while len(tiles) % 6:
        tiles.append(np.zeros_like(tiles[0]))
    rows = [np.hstack(tiles[i:i + 6]) for i in range(0, len(tiles), 6)]
    cv2.imwrite(path, np.vstack(rows), [cv2.IMWRITE_JPEG_QUALITY, 80])


def label(clip, clips_dir, out_dir, sheets_dir):
    frames = list(frames_of(os.path.join(clips_dir, clip + '.mp4')))
    masks = [SILHOUETTES[clip](f) for f in frames]
    with open(os.path.join(out_dir, clip + '.csv'), 'w', newline='') as fh:
        w = csv.writer(fh, lineterminator='\n')
        w.writerow(['frame', 'centroid_x', 'centroid_y', 'area', 'x', 'y', 'width', 'height',
                    'inner_x', 'inner_y', 'luma_mean'])
        for i, (f, m) in enumerate(zip(frames, masks)):
            mo = cv2.moments(m, True)
            if mo['m00'] == 0:
                raise SystemExit(f'label_truth: {clip} frame {i}: no silhouette found')
            x, y, bw, bh = cv2.boundingRect(m)
            ix, iy = farthest_inside(m)
            luma = cv2.cvtColor(f, cv2.COLOR_BGR2GRAY).mean()
            w.writerow([i, f"{mo['m10'] / mo['m00']:.2f}", f"{mo['m01'] / mo['m00']:.2f}",
                        int(mo['m00']), x, y, bw, bh, ix, iy, f'{luma:.2f}'])
    with gzip.open(os.path.join(out_dir, clip + '_outlines.csv.gz'), 'wt', newline='') as fh:
        w = csv.writer(fh, lineterminator='\n')
        w.writerow(['frame', 'kind', 'points'])
        for i, m in enumerate(masks):
            for kind, poly in outlines(m):
                w.writerow([i, kind, ' '.join(f'{x}:{y}' for x, y in poly)])
    if sheets_dir:
        for k in range(0, len(frames), 72):
            sheet(frames[k:k + 72], masks[k:k + 72], k, 3,
                  os.path.join(sheets_dir, f'{clip}_{k:03d}.jpg'))
    print(f'{clip}: {len(frames)} frames labelled')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('clips_dir')
    ap.add_argument('out_dir')
    ap.add_argument('--sheets', help='write contact sheets here for checking by eye')
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    if args.sheets:
        os.makedirs(args.sheets, exist_ok=True)
    for clip in SILHOUETTES:
        label(clip, args.clips_dir, args.out_dir, args.sheets)


if __name__ == '__main__':
    main()
