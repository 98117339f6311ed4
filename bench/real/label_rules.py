"""label_clips.py's segmentation rules for the clips of pymecavideo and visp-images-data (pucks
on an air table, a thrown ball, an ellipse, a cube), and the helpers every rule uses: colour,
shape and motion rules, never any tracker's output (label_clips.py's docstring says how they are
used and checked)."""
import cv2
import numpy as np

from truth_geometry import disc, fill_holes


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
