"""The 3D-mouse benchmark's pictures: real photographed objects, cut out of opencv-doc's images by
a mask made here (GrabCut from a rectangle, its largest piece, holes filled), moved over real
photographs along a scripted path (script.py), with motion blur, lighting drift and sensor noise.

Nothing here knows projtrack: the truth of every frame (the object's scale, centre and area) is
the script's, and the pixels are rendered from it.
"""
import functools
import math

import cv2
import numpy as np

DATA = "/usr/share/doc/opencv-doc/examples/data"

# The objects: an image and the rectangle GrabCut starts from (x, y, width, height). Chosen for
# their variety: a smooth fruit with highlights, a drawn fish with black outlines and many
# colours, a butterfly of black and white patches, a furry animal whose edge is ragged.
OBJECTS = {
    "apple": ("apple.jpg", (20, 10, 480, 470)),
    "fish": ("HappyFish.jpg", (40, 10, 215, 180)),
    "butterfly": ("butterfly.jpg", (5, 40, 480, 260)),
    "squirrel": ("squirrel_cls.jpg", (120, 120, 260, 300)),
}
OBJECT_WORDS = {"apple": "an apple", "fish": "a drawn fish", "butterfly": "a butterfly",
                "squirrel": "a squirrel"}
# The backgrounds: photographs of buildings, streets, a city from the air, graffiti, a desk.
BACKGROUNDS = ["home.jpg", "building.jpg", "aero1.jpg", "leuvenA.jpg", "graf1.png", "stuff.jpg"]


class Sprite:
    """A cut-out object: its colours (float BGR), its mask (0..1, edges softened by a pixel) and
    the mask's area in its own pixels."""

    def __init__(self, bgr, alpha):
        self.bgr = bgr.astype(np.float32)
        self.alpha = alpha.astype(np.float32)
        self.area = float(alpha.sum())
        self.height, self.width = alpha.shape


def _largest_piece_filled(mask):
    """The largest 8-connected piece of `mask` (0/255) with its holes filled."""
    n, labels, stats, _ = cv2.connectedComponentsWithStats(mask)
    if n < 2:
        raise RuntimeError("GrabCut found no object")
    k = 1 + int(np.argmax(stats[1:, cv2.CC_STAT_AREA]))
    piece = np.where(labels == k, 255, 0).astype(np.uint8)
    outside = piece.copy()
    cv2.floodFill(outside, np.zeros((piece.shape[0] + 2, piece.shape[1] + 2), np.uint8), (0, 0),
                  255)
    return piece | cv2.bitwise_not(outside)


@functools.lru_cache(maxsize=None)
def sprite(name):
    """The object `name` of OBJECTS, cut out and cropped to its mask's box."""
    path, rect = OBJECTS[name]
    image = cv2.imread(f"{DATA}/{path}")
    if image is None:
        raise FileNotFoundError(f"{DATA}/{path} (Debian package opencv-doc)")
    cv2.setRNGSeed(1)  # GrabCut's colour models start from k-means: the same mask every run
    labels = np.zeros(image.shape[:2], np.uint8)
    cv2.grabCut(image, labels, rect, np.zeros((1, 65)), np.zeros((1, 65)), 5,
                cv2.GC_INIT_WITH_RECT)
    mask = _largest_piece_filled(
        np.where((labels == cv2.GC_FGD) | (labels == cv2.GC_PR_FGD), 255, 0).astype(np.uint8))
    x, y, w, h = cv2.boundingRect(mask)
    alpha = cv2.GaussianBlur(mask[y:y + h, x:x + w].astype(np.float32) / 255, (3, 3), 0)
    return Sprite(image[y:y + h, x:x + w], alpha)


@functools.lru_cache(maxsize=None)
def background(name, width, height):
    """The photograph `name`, cropped to the frame's aspect and resized to it (float BGR)."""
    image = cv2.imread(f"{DATA}/{name}")
    if image is None:
        raise FileNotFoundError(f"{DATA}/{name} (Debian package opencv-doc)")
    h, w = image.shape[:2]
    if w * height > h * width:  # wider than the frame: keep the middle
        cw = h * width // height
        image = image[:, (w - cw) // 2:(w - cw) // 2 + cw]
    else:
        ch = w * height // width
        image = image[(h - ch) // 2:(h - ch) // 2 + ch]
    return cv2.resize(image, (width, height), interpolation=cv2.INTER_AREA).astype(np.float32)


def _warp_into(acc_bgr, acc_alpha, sp, scale, angle, cx, cy):
    """Adds the sprite, scaled by `scale` (its height in frame pixels over its own), turned by
    `angle` degrees and centred at (cx, cy), premultiplied, into the accumulators: only over
    the box it covers, which it returns (x0, y0, x1, y1; None when outside the frame)."""
    m = cv2.getRotationMatrix2D((sp.width / 2, sp.height / 2), angle, scale)
    m[:, 2] += (cx - sp.width / 2, cy - sp.height / 2)
    corners = np.array([[0, 0, 1], [sp.width, 0, 1], [0, sp.height, 1], [sp.width, sp.height, 1]],
                       np.float64) @ m.T
    fh, fw = acc_alpha.shape
    x0 = max(int(math.floor(corners[:, 0].min())) - 1, 0)
    y0 = max(int(math.floor(corners[:, 1].min())) - 1, 0)
    x1 = min(int(math.ceil(corners[:, 0].max())) + 2, fw)
    y1 = min(int(math.ceil(corners[:, 1].max())) + 2, fh)
    if x1 <= x0 or y1 <= y0:
        return None
    m[:, 2] -= (x0, y0)
    size = (x1 - x0, y1 - y0)
    a = cv2.warpAffine(sp.alpha, m, size, flags=cv2.INTER_LINEAR, borderValue=0)
    c = cv2.warpAffine(sp.bgr, m, size, flags=cv2.INTER_LINEAR, borderValue=0)
    acc_alpha[y0:y1, x0:x1] += a
    acc_bgr[y0:y1, x0:x1] += c * a[..., None]
    return x0, y0, x1, y1


class NoiseBank:
    """Sensor noise without drawing a frame of normals per frame: a few fields drawn once, a
    random window of one per frame, kept as its positive and negative parts for saturating
    8-bit adds."""

    MARGIN = 32

    def __init__(self, sigma, width, height, rng, fields=4):
        self.fields = []
        for _ in range(fields):
            n = rng.normal(0.0, sigma, (height + self.MARGIN, width + self.MARGIN, 3))
            self.fields.append((np.clip(np.rint(n), 0, 255).astype(np.uint8),
                                np.clip(np.rint(-n), 0, 255).astype(np.uint8)))
        self.width, self.height = width, height

    def add(self, image, rng):
        pos, neg = self.fields[rng.integers(len(self.fields))]
        x, y = rng.integers(self.MARGIN, size=2)
        window = (slice(y, y + self.height), slice(x, x + self.width))
        return cv2.subtract(cv2.add(image, pos[window]), neg[window])


def render(seq, frame, noise, rng):
    """Frame `frame` of sequence `seq` (script.Sequence) as 8-bit BGR, its noise from `noise` (a
    NoiseBank). Motion blur: the object is drawn at `seq.blur_samples` instants across the
    shutter (half a frame) and averaged, so what moves or grows fast smears as a camera's
    exposure smears it."""
    sp = sprite(seq.object)
    bg = background(seq.background, seq.width, seq.height)
    acc_bgr = np.zeros_like(bg)
    acc_alpha = np.zeros(bg.shape[:2], np.float32)
    k = seq.blur_samples
    box = None
    for i in range(k):
        t = (frame + 0.5 * (i + 0.5) / k - 0.25) / seq.fps
        pose = seq.pose(t)
        b = _warp_into(acc_bgr, acc_alpha, sp, pose.scale * seq.pixels_per_sprite_pixel(),
                       pose.angle, pose.x, pose.y)
        if b:
            box = b if box is None else (min(box[0], b[0]), min(box[1], b[1]),
                                         max(box[2], b[2]), max(box[3], b[3]))
    out = bg.astype(np.uint8)
    if box:
        x0, y0, x1, y1 = box
        a = acc_alpha[y0:y1, x0:x1, None] / k
        roi = bg[y0:y1, x0:x1] * (1 - a) + acc_bgr[y0:y1, x0:x1] / k
        out[y0:y1, x0:x1] = np.clip(roi, 0, 255).astype(np.uint8)
    out = cv2.convertScaleAbs(out, alpha=seq.light(frame / seq.fps))
    return noise.add(out, rng)


def object_area(seq, t):
    """The object's area in frame pixels at time `t`: its mask's, scaled."""
    sp = sprite(seq.object)
    s = seq.pose(t).scale * seq.pixels_per_sprite_pixel()
    return sp.area * s * s


def object_box(seq, t):
    """The object's box in the frame at time `t` (x, y, width, height), rounded outward."""
    sp = sprite(seq.object)
    pose = seq.pose(t)
    m = cv2.getRotationMatrix2D((sp.width / 2, sp.height / 2), pose.angle,
                                pose.scale * seq.pixels_per_sprite_pixel())
    m[:, 2] += (pose.x - sp.width / 2, pose.y - sp.height / 2)
    ys, xs = np.nonzero(sp.alpha > 0.5)
    pts = np.stack([xs, ys, np.ones_like(xs)], 1).astype(np.float64) @ m.T
    x0, y0 = np.floor(pts.min(0)).astype(int)
    x1, y1 = np.ceil(pts.max(0)).astype(int)
    return int(x0), int(y0), int(x1 - x0 + 1), int(y1 - y0 + 1)
