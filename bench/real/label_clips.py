#!/usr/bin/python3
"""Ground truth for real clips shipped in Debian packages: one object's silhouette on every
frame, made by colour / shape / motion segmentation rules, never from any tracker's output.

    label_clips.py CLIPS_ROOT OUT_DIR [--sheets DIR] [--only CLIP,...]

CLIPS_ROOT is a directory into which the packages were unpacked with `dpkg -x` (so that it holds
usr/share/pymecavideo/..., usr/share/visp-images-data/..., usr/share/doc/opencv-doc/...); a
file missing there is looked for at the same path under / (an installed package). Writes
OUT_DIR/<clip>.csv (per frame: centroid, area, bounding box, the silhouette's point farthest from
its border, mean luma for checking that a decoder gives the same frames; area 0 and empty fields
where the object is not in view) and OUT_DIR/<clip>_outlines.csv.gz (the silhouette's outer and
hole contours, simplified to within one pixel). With --sheets, contact sheets with the silhouette
outlined, for checking by eye. Hand corrections are read from label_clips_corrections.csv next to this
script. truth/README.md says what each label is, how it was checked and its known errors.

Videos are decoded with cv2.VideoCapture (FFmpeg, full-range BGR); pgm sequences are read with
cv2.imread in sorted name order. Frame numbers count from 0 in decoding order.
"""
import argparse
import csv
import glob
import gzip
import os

import cv2
import numpy as np

from truth_geometry import disc, farthest_inside, fill_holes
from truth_geometry import outlines_of as outlines

HERE = os.path.dirname(os.path.abspath(__file__))
MECA = 'usr/share/pymecavideo/data/video/'
VISP = 'usr/share/visp-images-data/ViSP-images/'
OCV = 'usr/share/doc/opencv-doc/examples/data/'


# ----------------------------------------------------------------------------------------------
# helpers

def components(mask, min_area=1):
    """[(label image, index, stats row, centroid)] of the 8-connected components."""
    n, labels, stats, cents = cv2.connectedComponentsWithStats(mask.astype(np.uint8), connectivity=8)
    return labels, [(k, stats[k], cents[k]) for k in range(1, n) if stats[k, 4] >= min_area]


def hull_mask(mask):
    out = np.zeros_like(mask, dtype=np.uint8)
    pts = cv2.findNonZero(mask.astype(np.uint8))
    if pts is not None:
        cv2.fillConvexPoly(out, cv2.convexHull(pts), 1)
    return out


def gray(bgr):
    return cv2.cvtColor(bgr, cv2.COLOR_BGR2GRAY)


# ----------------------------------------------------------------------------------------------
# hand corrections (label_clips_corrections.csv: clip,first,last,op,shape,coords,why)

def load_corrections(path):
    rows = []
    if os.path.exists(path):
        with open(path, newline='') as fh:
            for r in csv.DictReader(line for line in fh if not line.startswith('#')):
                r['first'], r['last'] = int(r['first']), int(r['last'])
                rows.append(r)
    return rows


def shape_mask(shape, coords, frame, first, last, size):
    """A box `x,y,w,h` (or `x,y,w,h>x,y,w,h`, moved linearly from frame `first` to `last`), a
    point `x,y` (or `x,y>x,y`, moved likewise) or a polygon `x:y x:y ...`, drawn filled."""
    h, w = size
    m = np.zeros((h, w), np.uint8)
    if shape == 'point':
        parts = [np.array([float(v) for v in p.split(',')]) for p in coords.split('>')]
        t = 0.0 if len(parts) == 1 or last == first else (frame - first) / (last - first)
        x, y = parts[0] + t * (parts[-1] - parts[0])
        if 0 <= round(x) < w and 0 <= round(y) < h:
            m[int(round(y)), int(round(x))] = 1
    elif shape == 'box':
        parts = [np.array([float(v) for v in p.split(',')]) for p in coords.split('>')]
        t = 0.0 if len(parts) == 1 or last == first else (frame - first) / (last - first)
        x, y, bw, bh = parts[0] + t * (parts[-1] - parts[0])
        cv2.rectangle(m, (int(round(x)), int(round(y))),
                      (int(round(x + bw)) - 1, int(round(y + bh)) - 1), 1, -1)
    elif shape == 'poly':
        pts = np.array([[int(v) for v in p.split(':')] for p in coords.split()], np.int32)
        cv2.fillPoly(m, [pts], 1)
    else:
        raise SystemExit(f'label_clips: unknown correction shape {shape}')
    return m


def guides_of(clip, corrections):
    """A function (frame, shape) -> the union of the clip's `clip` shapes on that frame, or
    None: labellers that follow an object through merges use them as guides."""
    rows = [r for r in corrections if r['clip'] == clip and r['op'] == 'clip']

    def guide(i, shape):
        mine = [r for r in rows if r['first'] <= i <= r['last']]
        if not mine:
            return None
        m = np.zeros(shape, np.uint8)
        for r in mine:
            m |= shape_mask(r['shape'], r['coords'], i, r['first'], r['last'], shape)
        return m
    return guide


def correct(clip, masks, corrections):
    """Applies the hand corrections of `clip` to the masks (a generator): `absent` empties the
    frame, `clip` keeps only what lies inside the shape, `remove` cuts the shape out, `add`
    paints it in, `hull` replaces the silhouette by the convex hull of it and the shape (a
    convex object's missed corner). In a frame, `clip` comes first, then `remove`, `add`,
    `hull`."""
    mine = [r for r in corrections if r['clip'] == clip]
    order = {'absent': 0, 'clip': 1, 'remove': 2, 'add': 3, 'hull': 4}
    for i, m in enumerate(masks):
        for r in sorted((r for r in mine if r['first'] <= i <= r['last']),
                        key=lambda r: order[r['op']]):
            if r['op'] == 'absent':
                m = np.zeros_like(m)
                continue
            s = shape_mask(r['shape'], r['coords'], i, r['first'], r['last'], m.shape)
            if r['op'] == 'hull':
                m = hull_mask(m | s)
            elif r['op'] == 'clip':
                m = m & s
            elif r['op'] == 'remove':
                m = m & (1 - s)
            elif r['op'] == 'add':
                m = m | s
        yield m


# ----------------------------------------------------------------------------------------------
# pymecavideo: pucks on an air table, seen from above (Principe_inertie, Force_constante,
# Effet_force_magnetique)

def skin_of(bgr):
    """Skin (the hand that launches the puck) by its red chroma: Cr > 135 (the table reads
    126-133, the puck's ring 127-134, the hand 137-170); Cb > 90 leaves out the yellow ruler of
    Force_constante (Cb about 60)."""
    ycc = cv2.cvtColor(bgr, cv2.COLOR_BGR2YCrCb)
    sk = ((ycc[..., 1] > 135) & (ycc[..., 2] > 90)).astype(np.uint8)
    return cv2.morphologyEx(sk, cv2.MORPH_OPEN, np.ones((3, 3), np.uint8))


def fit_circle_fixed_radius(points, r0, centre):
    """Centre of the circle of radius r0 that best fits `points` (Gauss-Newton), dropping the
    points more than 3 px off (later 2.5 median deviations, at least 1.5 px): notches cut by
    a finger or a printed label, the frame's border."""
    c = np.array(centre, float)
    for it in range(40):
        d = points - c
        n = np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-6)
        res = n - r0
        keep = np.abs(res) < (3.0 if it < 5 else max(1.5, 2.5 * np.median(np.abs(res))))
        if keep.sum() < 10:
            break
        jac = -(d / n[:, None])[keep]
        step = np.linalg.lstsq(jac, -res[keep], rcond=None)[0]
        c += step
        if it >= 6 and np.hypot(*step) < 1e-3:
            break
    return c


def puck_masks(read, start, r_core, r_puck, first_in_view=2):
    """The puck: a disc of the puck's radius around the centre of its dark top, without the
    fingers lying on it.

    Frames before `first_in_view` are the title card ("LYCEE JEAN BART", a still shared by the
    clips, showing a puck beside a ruler): a different shot whose puck cannot be told to be this
    clip's, so the object is not in view there. The camera is fixed above the table, so the puck
    always projects to a circle of the same size (measured on radial luma profiles: the dark top
    ends at r_core, the ring's outer dark edge at r_puck). Its dark top is the part that can be
    segmented reliably: grey < 105 (top 72-90, ring 130-160, table 175-185), not skin, opened by
    a 5 px disc, the component nearest the puck's previous centre, holes (the printed labels)
    filled. A circle of radius r_core is fitted to that component's outline, leaving out points
    on the frame's border and next to skin, so a puck cut by the border or covered by fingers
    is still centred right. The silhouette is the disc of radius r_puck there, clipped to the
    frame, minus skin (fingers in front of the puck).
    """
    prev = np.array(start, float)
    for i, f in enumerate(read()):
        h, w = f.shape[:2]
        if i < first_in_view:
            yield np.zeros((h, w), np.uint8)
            continue
        sk = skin_of(f)
        dark = ((gray(f) < 105) & (sk == 0)).astype(np.uint8)
        dark = cv2.morphologyEx(dark, cv2.MORPH_OPEN, disc(5))
        labels, comps = components(dark, min_area=150)
        k, _, cen = min(comps, key=lambda c: np.hypot(*(c[2] - prev)))
        top = fill_holes((labels == k).astype(np.uint8))
        cs, _ = cv2.findContours(top, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        p = max(cs, key=len).reshape(-1, 2)
        near_skin = cv2.dilate(sk, np.ones((5, 5), np.uint8))
        ok = ((p[:, 0] > 1) & (p[:, 0] < w - 2) & (p[:, 1] > 1) & (p[:, 1] < h - 2) &
              (near_skin[p[:, 1], p[:, 0]] == 0))
        dist = cv2.distanceTransform(np.pad(top, 1), cv2.DIST_L2, 5)[1:-1, 1:-1]
        iy, ix = np.unravel_index(int(np.argmax(dist)), dist.shape)
        c = fit_circle_fixed_radius(p[ok].astype(float), r_core, (ix, iy))
        prev = c
        m = np.zeros((h, w), np.uint8)
        cv2.circle(m, (int(round(c[0] * 16)), int(round(c[1] * 16))), int(round(r_puck * 16)),
                   1, -1, lineType=cv2.LINE_8, shift=4)
        yield m & (1 - sk)


def inertie_masks(read):
    """Principe_inertie: the only puck, launched from the left edge by a hand, sliding to the
    right edge. Top radius 26.1 px, ring's outer edge 37 px (the same puck as Force_constante)."""
    return puck_masks(read, start=(75, 112), r_core=26.1, r_puck=37.0)


def force_masks(read):
    """Force_constante: the only puck, pushed by a hand whose fingers lie on it (frames 2-8),
    sliding to the right edge above the yellow ruler. Same puck as Principe_inertie."""
    return puck_masks(read, start=(65, 111), r_core=26.1, r_puck=37.0)


def magnet_masks(read):
    """Effet_force_magnetique: of the two pucks, the one that moves first and most -- on frame 2
    the upper one, near the top right (centre about (295, 74)), next to the hand that launched
    it; it runs down-left, passes above the other (nearly still, lower) puck and ends at the
    left. A thinner white rim than the other clips' puck: top radius 26.7 px, the rim's outer
    edge 33 px (the dark lines just outside the rim at 12 and 6 o'clock are the codec's ringing,
    they go round the whole rim, fainter elsewhere)."""
    return puck_masks(read, start=(295, 74), r_core=26.7, r_puck=33.0)


# ----------------------------------------------------------------------------------------------
# pymecavideo balle1-vp9: a small red ball thrown across a classroom

def balle1_masks(read):
    """The red ball, from the hand that holds it (frame 0) to its last frame.

    Red is told by its chroma: the ball's Cr is 155-170, the room's 125-135, the hand's 127-145,
    the yellow pole's up to about 145. VP9 keeps chroma at half resolution, so the ball's edge
    is a ramp 2-3 px wide: the silhouette is Cr > 146 (the ramp's middle), grown by one pixel
    into Cr > 136 (the ramp's foot, where the ball's luma edge is) but not into the yellow pole
    (Cb about 100; the ball's is 110-120), and its holes filled. Of the red components (a pink
    object on the left table and a dark red one under it are red too) the ball is the one
    nearest its position predicted from the last two frames (within 25 px; after frames without
    the ball the gate widens by 25 px a frame). When no component is in the gate
    the ball is out of the picture: it leaves through the bottom edge on frames 236-241 (the
    bottom row is black) and comes back.
    """
    pos, vel, lost = np.array([88.0, 126.0]), np.zeros(2), 0
    for i, f in enumerate(read()):
        ycc = cv2.cvtColor(f, cv2.COLOR_BGR2YCrCb)
        cr, cb = ycc[..., 1], ycc[..., 2]
        core = (cr > 146).astype(np.uint8)
        red = core | (cv2.dilate(core, np.ones((3, 3), np.uint8)) & (cr > 136) & (cb > 106))
        labels, comps = components(red, min_area=3)
        pred = pos + vel
        near = [c for c in comps if np.hypot(*(c[2] - pred)) < 25 * (1 + lost)]
        if not near:
            lost += 1
            yield np.zeros(cr.shape, np.uint8)
            continue
        k, _, cen = min(near, key=lambda c: np.hypot(*(c[2] - pred)))
        vel = cen - pos if (lost == 0 and i > 0) else np.zeros(2)
        pos, lost = cen, 0
        yield fill_holes((labels == k).astype(np.uint8))


# ----------------------------------------------------------------------------------------------
# ViSP ellipse-1: a large white ellipse on black, leaving through the frame's edge

def ellipse_masks(read):
    """The white ellipse, the part inside the frame.

    White against black: grey > 128, the middle between the card (about 30) and the ellipse
    (about 220), so the outline sits at the edge's half-height. The ellipse is the largest white
    component on frame 0, then the component overlapping the previous frame's silhouette most.
    On frames 30-48 a second white region shows in the top left corner, never touching the
    ellipse: it is not the ellipse -- the part of an ellipse inside the rectangular frame is
    convex, hence in one piece (the silhouette's area is within 0.6 % of its convex hull's on
    every frame), and that region is bounded by a straight edge, not an elliptic arc: it is
    what lies beyond the black card's straight edge. Holes (none expected) are filled.
    """
    prev = None
    for f in read():
        white = (gray(f) > 128).astype(np.uint8)
        labels, comps = components(white, min_area=20)
        if prev is None:
            k = max(comps, key=lambda c: c[1][4])[0]
        else:
            k = max(comps, key=lambda c: int(((labels == c[0]) & (prev > 0)).sum()))[0]
        prev = fill_holes((labels == k).astype(np.uint8))
        yield prev


# ----------------------------------------------------------------------------------------------
# ViSP mbt/cube: a printed cube on a table, moving camera

def local_sd(g, k):
    g = g.astype(np.float32)
    mu = cv2.blur(g, (k, k))
    return np.sqrt(np.maximum(cv2.blur(g * g, (k, k)) - mu * mu, 0))


def cube_masks(read):
    """The cube's visible faces: the convex hull of a GrabCut segmentation seeded by the cube's
    printed texture (a cube projects to a convex hexagon).

    1. Seed: the cube's print is the only textured thing near it (the table, the paper sheet
       under the cube and the cylinder are smooth): local standard deviation over 5x5 > 8,
       closed by a 7 px disc and opened by a 9 px disc (removes the thin bands along the
       cylinder's and the paper's edges); the component nearest the previous seed's centre.
       This misses the smooth parts of the print (the large pale picture on the front face from
       frame 60 on), hence step 2.
    2. GrabCut (grey levels, 5 iterations) on the seed's hull grown by 30 px: the seed eroded by
       2 px is certain cube, the hull grown by 10 px probable cube except its smooth pixels
       (5x5 deviation averaged over 5x5 < 3: the cube's soft shadow and the bare paper), which
       are probable background like the rest of the ring, and beyond it background.
    3. The GrabCut foreground opened by a 5 px disc (drops the thin line along the paper's edge
       that touches the cube's bottom corner on frames 90-110), its largest component, and the
       convex hull of that.
    4. On frames 60-135 the front face's lower left corner is dark print in the cube's own shade
       and GrabCut often rounds it off (up to about 250 px²): the corner is put back where the
       silhouette's left edge meets the line of its bottom edge (lower_left_corner), and the
       hull taken again. On the other frames the silhouette's lower left is another vertex (the
       left face's) and that construction does not hold; frames 186-205 are corrected by hand
       (label_clips_corrections.csv).
    """
    prev = None
    for i, f in enumerate(read()):
        g = gray(f)
        sd = local_sd(g, 5)
        tex = cv2.morphologyEx((sd > 8).astype(np.uint8), cv2.MORPH_CLOSE, disc(7))
        tex = cv2.morphologyEx(tex, cv2.MORPH_OPEN, disc(9))
        labels, comps = components(tex, min_area=800)
        if prev is None:
            k, _, prev = max(comps, key=lambda c: c[1][4])
        else:
            k, _, prev = min(comps, key=lambda c: np.hypot(*(c[2] - prev)))
        seed = (labels == k).astype(np.uint8)
        hull0 = hull_mask(seed)
        gc = np.full(g.shape, cv2.GC_BGD, np.uint8)
        gc[cv2.dilate(hull0, disc(61)) > 0] = cv2.GC_PR_BGD
        gc[cv2.dilate(hull0, disc(21)) > 0] = cv2.GC_PR_FGD
        smooth = cv2.blur(sd, (5, 5)) < 3
        gc[smooth & (gc == cv2.GC_PR_FGD)] = cv2.GC_PR_BGD
        gc[cv2.erode(seed, disc(5)) > 0] = cv2.GC_FGD
        x, y, w, h = cv2.boundingRect(cv2.dilate(hull0, disc(81)))
        sub = gc[y:y + h, x:x + w].copy()
        bgd, fgd = np.zeros((1, 65), np.float64), np.zeros((1, 65), np.float64)
        cv2.setRNGSeed(0)
        cv2.grabCut(f[y:y + h, x:x + w].copy(), sub, None, bgd, fgd, 5, cv2.GC_INIT_WITH_MASK)
        fg = np.zeros_like(g)
        fg[y:y + h, x:x + w] = ((sub == cv2.GC_FGD) | (sub == cv2.GC_PR_FGD))
        fg = cv2.morphologyEx(fg, cv2.MORPH_OPEN, disc(5))
        labels, comps = components(fg)
        k = max(comps, key=lambda c: c[1][4])[0]
        m = hull_mask(labels == k)
        if 60 <= i <= 135:
            p = lower_left_corner(m)
            if p is not None:
                m = hull_mask(m | point_mask(p, m.shape))
        yield m


def point_mask(p, shape):
    m = np.zeros(shape, np.uint8)
    x, y = int(round(p[0])), int(round(p[1]))
    if 0 <= x < shape[1] and 0 <= y < shape[0]:
        m[y, x] = 1
    return m


def lower_left_corner(m, reach=25):
    """Where the silhouette's left edge (its contour points within 1 px of its leftmost column)
    meets the line of its bottom-left edge (the lower envelope of the contour's half nearest the
    bottom vertex, fitted by least squares), if that lies within `reach` px of the contour."""
    cs, _ = cv2.findContours(m, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
    c = max(cs, key=len).reshape(-1, 2).astype(float)
    minx = c[:, 0].min()
    left = c[c[:, 0] <= minx + 1.0]
    if len(left) < 8:
        return None
    b = c[np.argmax(c[:, 1])]
    seg = c[(c[:, 0] >= b[0] - 0.5 * (b[0] - minx)) & (c[:, 0] <= b[0] - 2) &
            (c[:, 1] > left[:, 1].max())]
    if len(seg) < 6:
        return None
    xs = np.unique(seg[:, 0])
    env = np.array([[x, seg[seg[:, 0] == x, 1].max()] for x in xs])
    slope, icpt = np.polyfit(env[:, 0], env[:, 1], 1)
    x = float(np.median(left[:, 0]))
    p = np.array([x, slope * x + icpt])
    if np.min(np.hypot(*(c - p).T)) > reach:
        return None
    return p


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


# ----------------------------------------------------------------------------------------------
# reading, writing, contact sheets

def reader(path):
    """A function giving a fresh iterator over the clip's frames (BGR)."""
    if '%' in path:
        names = sorted(glob.glob(os.path.join(os.path.dirname(path), '*.pgm')))
        if not names:
            raise SystemExit(f'label_clips: no frames at {path}')

        def read():
            for n in names:
                yield cv2.cvtColor(cv2.imread(n, cv2.IMREAD_GRAYSCALE), cv2.COLOR_GRAY2BGR)
        return read

    def read():
        cap = cv2.VideoCapture(path)
        if not cap.isOpened():
            raise SystemExit(f'label_clips: cannot read {path}')
        while True:
            ok, frame = cap.read()
            if not ok:
                return
            yield frame
    return read


def draw_outline(img, mask, scale=1.0, offset=(0, 0), colour=(255, 0, 255)):
    cs, _ = cv2.findContours(mask, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_NONE)
    for c in cs:
        pts = ((c.reshape(-1, 2) - offset + 0.5) * scale).astype(np.int32)
        cv2.polylines(img, [pts], True, colour, 1)


def tint(frame, mask):
    """The frame with the silhouette tinted magenta (30 %), so that dark objects show it."""
    out = frame.copy()
    m = mask.astype(bool)
    out[m] = (0.7 * out[m] + 0.3 * np.array([255, 0, 255])).astype(np.uint8)
    return out


def tile(frame, mask, i, sheet):
    """A contact-sheet tile: the whole frame scaled by sheet['scale'], or with sheet['crop']
    = (w, h) a crop of that size around the silhouette's box centre (the last one seen when
    the object is out of view) zoomed by sheet['zoom']; the outline in magenta (and in
    whole-frame tiles a green box around it, small objects being hard to see) over a 30 %
    magenta tint, the frame number, and 'out' when the object is not in view."""
    h, w = frame.shape[:2]
    if 'crop' in sheet:
        cw, ch = sheet['crop']
        cx, cy = sheet['_centre']
        x0 = int(np.clip(cx - cw // 2, 0, max(0, w - cw)))
        y0 = int(np.clip(cy - ch // 2, 0, max(0, h - ch)))
        z = sheet['zoom']
        img = cv2.resize(tint(frame, mask)[y0:y0 + ch, x0:x0 + cw], None, fx=z, fy=z,
                         interpolation=cv2.INTER_NEAREST)
        draw_outline(img, mask[y0:y0 + ch, x0:x0 + cw].copy(), z)
    else:
        z = sheet['scale']
        img = cv2.resize(tint(frame, mask), None, fx=z, fy=z, interpolation=cv2.INTER_AREA)
        draw_outline(img, mask, z)
        if mask.any() and sheet.get('box'):
            x, y, bw, bh = cv2.boundingRect(mask)
            cv2.rectangle(img, (int(x * z) - 4, int(y * z) - 4),
                          (int((x + bw) * z) + 4, int((y + bh) * z) + 4), (0, 255, 0), 1)
    text = str(i) + ('' if mask.any() else ' out')
    cv2.putText(img, text, (3, 15), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (0, 0, 0), 3)
    cv2.putText(img, text, (3, 15), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (0, 255, 255), 1)
    return img


def write_sheets(tiles, cols, per_sheet, path_pattern):
    paths = []
    for s in range(0, len(tiles), per_sheet):
        part = [t for _, t in tiles[s:s + per_sheet]]
        th = max(t.shape[0] for t in part)
        tw = max(t.shape[1] for t in part)
        part = [cv2.copyMakeBorder(t, 0, th - t.shape[0] + 2, 0, tw - t.shape[1] + 2,
                                   cv2.BORDER_CONSTANT, value=(40, 40, 40)) for t in part]
        while len(part) % cols:
            part.append(np.zeros_like(part[0]))
        rows = [np.hstack(part[r:r + cols]) for r in range(0, len(part), cols)]
        path = path_pattern.format(first=tiles[s][0], last=tiles[min(s + per_sheet, len(tiles)) - 1][0])
        cv2.imwrite(path, np.vstack(rows))
        paths.append(path)
    return paths


HEADER = ['frame', 'centroid_x', 'centroid_y', 'area', 'x', 'y', 'width', 'height',
          'inner_x', 'inner_y', 'luma_mean']


def label(clip, spec, clips_root, out_dir, sheets_dir, corrections):
    path = os.path.join(clips_root, spec['path'])
    if not os.path.exists(os.path.dirname(path) if '%' in path else path):
        path = os.path.join('/', spec['path'])
    read = reader(path)
    report = []
    if spec.get('guided'):
        masks = spec['masks'](read, guides=guides_of(clip, corrections), report=report)
    else:
        masks = spec['masks'](read)
    masks = correct(clip, masks, corrections)
    sheet = dict(spec.get('sheet', {'scale': 0.5, 'step': 1}))
    overview = spec.get('overview')
    closeups = set(spec.get('closeups', []))
    tiles, close_tiles, over_tiles, n_in = [], [], [], 0
    first_in = None
    with open(os.path.join(out_dir, clip + '.csv'), 'w', newline='') as fh, \
            gzip.open(os.path.join(out_dir, clip + '_outlines.csv.gz'), 'wt', newline='') as gz:
        w = csv.writer(fh, lineterminator='\n')
        w.writerow(HEADER)
        wo = csv.writer(gz, lineterminator='\n')
        wo.writerow(['frame', 'kind', 'points'])
        for i, (f, m) in enumerate(zip(read(), masks)):
            m = m.astype(np.uint8)
            luma = f'{gray(f).mean():.2f}'
            mo = cv2.moments(m, True)
            if mo['m00'] == 0:
                w.writerow([i, '', '', 0, '', '', '', '', '', '', luma])
            else:
                n_in += 1
                x, y, bw, bh = cv2.boundingRect(m)
                ix, iy = farthest_inside(m)
                if first_in is None:
                    first_in = (i, ix, iy)
                w.writerow([i, f"{mo['m10'] / mo['m00']:.2f}", f"{mo['m01'] / mo['m00']:.2f}",
                            int(mo['m00']), x, y, bw, bh, ix, iy, luma])
                sheet['_centre'] = (x + bw // 2, y + bh // 2)
                for kind, poly in outlines(m):
                    wo.writerow([i, kind, ' '.join(f'{px}:{py}' for px, py in poly)])
            if sheets_dir and '_centre' not in sheet:
                sheet['_centre'] = spec.get('centre0', (f.shape[1] // 2, f.shape[0] // 2))
            if sheets_dir and i % sheet['step'] == 0 and i <= sheet.get('until', i):
                tiles.append((i, tile(f, m, i, sheet)))
            if sheets_dir and overview and i % overview['step'] == 0:
                over_tiles.append((i, tile(f, m, i, overview)))
            if sheets_dir and i in closeups:
                close = dict(spec['closeup'])
                close['_centre'] = sheet['_centre']
                close_tiles.append((i, tile(f, m, i, close)))
    total = i + 1
    if sheets_dir:
        write_sheets(tiles, sheet.get('cols', 6), sheet.get('per_sheet', 48),
                     os.path.join(sheets_dir, clip + '-{first:03d}-{last:03d}.png'))
        if over_tiles:
            write_sheets(over_tiles, overview.get('cols', 8), overview.get('per_sheet', 48),
                         os.path.join(sheets_dir, clip + '-overview-{first:03d}-{last:03d}.png'))
        if close_tiles:
            write_sheets(close_tiles, spec['closeup'].get('cols', 4), 24,
                         os.path.join(sheets_dir, clip + '-closeup-{first:03d}-{last:03d}.png'))
    print(f'{clip}: {total} frames, object in view on {n_in}; first in view {first_in}')
    if report:
        print(f'{clip}: unguided frames where the object may have merged with another: {report}')


# ----------------------------------------------------------------------------------------------

CLIPS = {
    'balle1': dict(path=MECA + 'balle1-vp9.avi', masks=balle1_masks, centre0=(88, 126),
                   sheet=dict(crop=(64, 48), zoom=3, step=3, cols=8, per_sheet=64),
                   overview=dict(scale=0.5, step=15, box=True, cols=5, per_sheet=20),
                   closeup=dict(crop=(32, 32), zoom=8, cols=6),
                   closeups=[0, 2, 4, 6, 8, 10, 88, 90, 92, 94, 96, 98, 100, 102, 104, 106, 108,
                             110, 132, 134, 135, 136, 137, 138, 141, 144, 145, 146, 147, 148, 149, 150,
                             151, 235, 242, 243, 290, 294]),
    'inertie': dict(path=MECA + 'Principe_inertie.avi', masks=inertie_masks,
                    sheet=dict(scale=0.75, step=1, cols=5, per_sheet=30),
                    closeup=dict(crop=(96, 96), zoom=3, cols=5),
                    closeups=list(range(2, 12)) + [25, 26, 27]),
    'force': dict(path=MECA + 'Force_constante.avi', masks=force_masks,
                  sheet=dict(scale=0.75, step=1, cols=5, per_sheet=30),
                  closeup=dict(crop=(96, 96), zoom=3, cols=5),
                  closeups=list(range(2, 12)) + [23, 24, 25]),
    'magnet': dict(path=MECA + 'Effet_force_magnetique.ogv', masks=magnet_masks,
                   sheet=dict(scale=0.75, step=1, cols=5, per_sheet=35),
                   closeup=dict(crop=(96, 96), zoom=3, cols=5),
                   closeups=[2, 3, 4, 14, 15, 16, 17, 18, 32, 33]),
    'cube': dict(path=VISP + 'mbt/cube/image%04d.pgm', masks=cube_masks,
                 sheet=dict(crop=(200, 200), zoom=1, step=3, cols=8, per_sheet=40),
                 closeup=dict(crop=(180, 180), zoom=2, cols=4),
                 closeups=[0, 36, 66, 84, 96, 114, 126, 168, 182, 186, 192, 198, 204, 206,
                           217]),
    'vtest': dict(path=OCV + 'vtest.avi', masks=vtest_masks, guided=True, centre0=(661, 282),
                  sheet=dict(crop=(110, 130), zoom=1.5, step=2, until=158, cols=10, per_sheet=40),
                  overview=dict(scale=0.25, step=20, box=True, cols=8, per_sheet=40),
                  closeup=dict(crop=(100, 120), zoom=3, cols=6),
                  closeups=[23, 25, 28, 31, 34, 37, 40, 44, 49, 53, 54, 55, 56, 57, 58, 61, 63,
                            101, 103, 105, 107, 108, 109, 110, 111, 129, 130, 131, 138, 139,
                            140, 141, 142, 147, 148, 149]),
    'megamind': dict(path=OCV + 'Megamind.avi', masks=megamind_masks,
                     sheet=dict(scale=0.25, step=3, cols=8, per_sheet=48),
                     closeup=dict(crop=(360, 264), zoom=1, cols=4),
                     closeups=[1, 2, 30, 60, 97, 98, 99, 120, 153, 154, 155, 180, 199, 200]),
    'ellipse': dict(path=VISP + 'ellipse-1/image.%04d.pgm', masks=ellipse_masks,
                    sheet=dict(scale=0.5, step=1, cols=6, per_sheet=50)),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('clips_root')
    ap.add_argument('out_dir')
    ap.add_argument('--sheets', help='write contact sheets here for checking by eye')
    ap.add_argument('--only', help='comma-separated clip names (default: all)')
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    if args.sheets:
        os.makedirs(args.sheets, exist_ok=True)
    corrections = load_corrections(os.path.join(HERE, 'label_clips_corrections.csv'))
    for clip in (args.only.split(',') if args.only else CLIPS):
        label(clip, CLIPS[clip], args.clips_root, args.out_dir, args.sheets, corrections)


if __name__ == '__main__':
    main()
