"""label_clips.py's segmentation rules for opencv-doc's clips: vtest.avi (a pedestrian on a
campus, guided by hand corrections) and Megamind.avi (a cartoon with shot cuts)."""
import cv2
import numpy as np

from label_rules import components, gray
from truth_geometry import disc, fill_holes


# ----------------------------------------------------------------------------------------------
# opencv-doc vtest.avi: pedestrians on a campus, static camera

def median_background(read, every=5):
    """Per-pixel median of every `every`-th frame: nobody stays on the same pixels for as much
    as half the clip (the two men who stand longest, by the sign post, stay about 125 of its 795
    frames), so the median is the empty scene."""
    return np.median(np.stack([f for i, f in enumerate(read()) if i % every == 0]),
                     axis=0).astype(np.uint8)


def fill_small_holes(mask, max_area):
    """Fills the holes (background not 4-connected to the border) of at most max_area px."""
    background = np.pad((mask == 0).astype(np.uint8), 1, constant_values=1)
    n, labels, stats, _ = cv2.connectedComponentsWithStats(background, connectivity=4)
    small = np.zeros(n, bool)
    small[1:] = stats[1:, cv2.CC_STAT_AREA] <= max_area
    small[labels[0, 0]] = False
    return (mask.astype(bool) | small[labels][1:-1, 1:-1]).astype(np.uint8)


def moving_of(bgr, background):
    """Foreground: some colour channel differs from the background by more than 30 (the
    walkers' dark clothes differ by 60-150), except the soft shadows around the feet: ground
    darkened evenly, every channel at 70-92 % of the background's, the three ratios within
    0.08 of each other (the black coat is at 10-35 %; the grey shoes are darker than 70 % --
    looser bounds, 60 % and 0.10, ate into the shoes on the close-ups; skin and jeans change the
    colour). Opened by 3x3 (noise), closed by a 5 px disc (a walker's thin gaps), holes up to
    40 px² filled -- not larger ones: the ground seen between the legs, closed off when the
    feet or their shadows touch, is not the walker."""
    diff = cv2.absdiff(bgr, background).max(axis=2)
    ratio = bgr.astype(np.float32) / (background.astype(np.float32) + 1.0)
    shadow = ((ratio.min(axis=2) >= 0.7) & (ratio.max(axis=2) <= 0.92) &
              (ratio.max(axis=2) - ratio.min(axis=2) <= 0.08))
    m = ((diff > 30) & ~shadow).astype(np.uint8)
    m = cv2.morphologyEx(m, cv2.MORPH_OPEN, np.ones((3, 3), np.uint8))
    return fill_small_holes(cv2.morphologyEx(m, cv2.MORPH_CLOSE, disc(5)), 40)


def vtest_masks(read, guides=None, report=None):
    """The woman in a black coat and dark trousers who, on frame 0, walks left at the right of
    the picture (box x 640-683, y 241-323, feet at about (650, 322)): she walks to the sign post
    in the middle, lingers behind and beside the two men who meet there, walks on left along
    the top path, turns back and walks down to the right, and leaves through the right edge.

    Her silhouette is the foreground (moving_of against the clip's median background) that is
    hers. While she walks alone that is one component, followed from frame to frame: the
    component containing her position predicted from her last two positions (or nearest to it,
    within 20 px of its box). Where she overlaps or touches other walkers, the frames are guided
    by hand (guides: the `clip` shapes for vtest in label_clips_corrections.csv, read on 3-5x close-ups):
    her silhouette is then the foreground inside her box or outline, without specks under
    40 px² (there the sign post and the sign, being background, may cut her in pieces). A component much larger than her running size
    outside guided frames is reported (`report`), so that no merge goes unguided. Once she has
    touched the picture's border and her component is gone, she has left: area 0 from then on.
    """
    bg = median_background(read)
    pos, vel, size, left_at, touched_border = None, np.zeros(2), None, None, False
    for i, f in enumerate(read()):
        fg = moving_of(f, bg)
        m = np.zeros_like(fg)
        if left_at is not None:
            yield m
            continue
        guide = guides(i, fg.shape) if guides else None
        if guide is not None:
            labels, comps = components(fg & guide, min_area=40)
            for k, _, _ in comps:
                m[labels == k] = 1
        else:
            labels, comps = components(fg, min_area=40)
            pred = np.array([650.0, 280.0]) if pos is None else pos + vel
            best = None
            for k, st, c in comps:
                x, y, w, h, a = st
                d = np.hypot(max(x - pred[0], 0, pred[0] - x - w), max(y - pred[1], 0, pred[1] - y - h))
                if d <= 20 and (best is None or (d, np.hypot(*(c - pred))) < best[0]):
                    best = ((d, np.hypot(*(c - pred))), k, st)
            if best is not None:
                m[labels == best[1]] = 1
                if size is not None and report is not None and best[2][4] > 1.6 * size:
                    report.append(i)
        mo = cv2.moments(m, True)
        if mo['m00'] == 0:
            if pos is not None and touched_border:
                left_at = i
            yield m
            continue
        c = np.array([mo['m10'] / mo['m00'], mo['m01'] / mo['m00']])
        vel = np.zeros(2) if pos is None else 0.5 * vel + 0.5 * (c - pos)
        pos = c
        x, y, w, h = cv2.boundingRect(m)
        touched_border = x == 0 or y == 0 or x + w == m.shape[1] or y + h == m.shape[0]
        if guide is None:
            size = mo['m00'] if size is None else 0.9 * size + 0.1 * mo['m00']
        yield m


# ----------------------------------------------------------------------------------------------
# opencv-doc Megamind.avi: a cartoon with shot cuts

# The shots, as found by shot_starts() and checked by eye, and what of the dress each shows.
MEGAMIND_SHOTS = [
    (0, 'out'),      # frame 0 is black
    (1, 'front'),    # Roxanne at her table, facing the camera, in her purple dress
    (98, 'strap'),   # over her shoulder onto the man: only the dress's strap, at the left edge
    (154, 'front'),  # Roxanne again, facing the camera
    (200, 'out'),    # close-up of the man: no part of Roxanne in view
]


def shot_starts(read, threshold=20.0):
    """Frames where a new shot starts: the mean absolute grey difference from the previous
    frame, both shrunk to 90x66, is above `threshold` (within a shot it stays under 6; at the
    cuts it is 34-45)."""
    starts, prev = [0], None
    for i, f in enumerate(read()):
        small = cv2.resize(gray(f), (90, 66), interpolation=cv2.INTER_AREA).astype(np.float32)
        if prev is not None and np.abs(small - prev).mean() > threshold:
            starts.append(i)
        prev = small
    return starts


def purple_of(bgr):
    """The dress's purple: hue 135-172 on OpenCV's 0-180 scale (the dress reads 155-170; the
    skin and the red-brown walls and seats 0-25 or above 172, the man's sweater about 105),
    saturation >= 70 (the lavender tablecloths in the background are greyer, though some of
    their pixels pass), value >= 15 (the deepest folds are near black)."""
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    h, s, v = hsv[..., 0], hsv[..., 1], hsv[..., 2]
    return ((h >= 135) & (h <= 172) & (s >= 70) & (v >= 15)).astype(np.uint8)


def megamind_masks(read):
    """Roxanne's purple dress, the object a user would point at in the first shot: the only
    large area of that colour in the film, so colour segmentation labels it reliably (her face
    and the man's share their warm tones with the lit background).

    The shots are found by shot_starts() and must match MEGAMIND_SHOTS, which says, by eye,
    which part of the dress each shows. In 'front' shots the dress is the largest purple
    component after a 7 px closing, with the components within 25 px of it that are at least
    2 % of its size (her arm and glass can cut it), holes filled; a final 5 px closing smooths
    the compression noise along its dark folds. In the over-the-shoulder shot only the dress's
    strap shows, over her shoulder at the left edge: the purple components whose centre is in
    the frame's lower left quarter (x < 180, y > 264; the tablecloth specks of that shot lie
    right of x = 190), closed by 5 px. In 'out' shots the dress is not in view.
    """
    starts = shot_starts(read)
    if starts != [s for s, _ in MEGAMIND_SHOTS]:
        raise SystemExit(f'label_clips: Megamind shots {starts} differ from MEGAMIND_SHOTS')
    for i, f in enumerate(read()):
        kind = [k for s, k in MEGAMIND_SHOTS if s <= i][-1]
        m = np.zeros(f.shape[:2], np.uint8)
        if kind == 'front':
            p = cv2.morphologyEx(purple_of(f), cv2.MORPH_CLOSE, disc(7))
            labels, comps = components(p, min_area=20)
            big = max(comps, key=lambda c: c[1][4])
            bx, by, bw, bh, ba = big[1]
            for k, st, _ in comps:
                x, y, w, h, a = st
                if k == big[0] or (a >= 0.02 * ba and x < bx + bw + 25 and x + w > bx - 25 and
                                   y < by + bh + 25 and y + h > by - 25):
                    m[labels == k] = 1
            m = cv2.morphologyEx(fill_holes(m), cv2.MORPH_CLOSE, disc(5))
        elif kind == 'strap':
            p = purple_of(f)
            labels, comps = components(p, min_area=10)
            edge = np.zeros_like(m)
            for k, st, c in comps:
                if st[0] == 0 and c[1] > f.shape[0] / 2:
                    edge[labels == k] = 1
            near = cv2.dilate(edge, disc(21))
            for k, st, c in comps:
                if c[0] < 180 and c[1] > f.shape[0] / 2 and (near[labels == k]).any():
                    m[labels == k] = 1
            m = cv2.morphologyEx(m, cv2.MORPH_CLOSE, disc(5))
        yield m
