#!/usr/bin/python3
"""projtrack demo: tracks a hand-shaped object in a generated video with known ground truth,
or (--clip cup, --clip box) a real held object in one of opencv-doc's clips.

Writes under --out (default out/):
  demo.webm  the video with projtrack's overlay (draw=true); <clip>.webm for a real clip
  demo.csv   one row per frame: projtrack's features next to the true centroid and area
             (<clip>.csv; the truth of the real clips is bench/real/truth/'s)
and prints a summary. Needs the plugin on GST_PLUGIN_PATH (./run demo sets it) and Debian's
python3-gst-1.0 and python3-numpy; the real clips need opencv-doc and gstreamer1.0-libav. Exit
code 0 when every frame was tracked (a real clip: any), 1 when not or the pipeline failed, 2 for
a bad option or a missing package.
"""
import csv
import gzip
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli import (FAILED, USAGE, Failure, gi_modules, gstreamer, module,  # noqa: E402
                 parse_launch, parser, positive_int, run)

np = module('demo', 'numpy', 'python3-numpy')
(Gst,) = gi_modules('demo', 'Gst')

FIELDS = ['frame', 'timestamp_s', 'status', 'centroid_x', 'centroid_y', 'area', 'x', 'y', 'width',
          'height', 'inner_point_x', 'inner_point_y', 'iterations', 'processing_ms',
          'true_centroid_x', 'true_centroid_y', 'true_area']


class HandScene:
    """A five-finger hand moving on a Lissajous path and growing/shrinking (depth), over a
    shaded, noisy background. mask(i) is the exact object; frame(i) is what the camera sees."""

    PERIOD = 300  # frames for one loop of the path (10 s at 30 fps), whatever the length

    def __init__(self, width, height, path=None):
        """path(i) -> (x, y, size) overrides the default Lissajous loop: x, y as fractions of
        the frame, size 1 for a hand about 200 px tall at 480 lines."""
        self.w, self.h = width, height
        self.path = path
        self.yy, self.xx = np.mgrid[0:height, 0:width].astype(np.float32)
        shade = 40 + 50 * self.yy / height + 12 * np.sin(self.xx / 23.0)
        self.background = np.stack([shade * 0.8, shade * 0.9, shade * 1.2], axis=-1)
        self.rng = np.random.default_rng(7)

    def pose(self, i):
        if self.path:
            fx, fy, size = self.path(i)
            return fx * self.w, fy * self.h, self.h / 480 * size
        t = i / self.PERIOD * 2 * math.pi
        scale = self.h / 480 * (1.0 + 0.25 * math.sin(2 * t))  # toward and away from the camera
        cx = self.w / 2 + 0.28 * self.w * math.sin(t)
        cy = self.h / 2 + 0.18 * self.h * math.sin(2 * t + 0.5)
        return cx, cy, scale

    def mask(self, i):
        cx, cy, s = self.pose(i)
        x, y = self.xx - cx, self.yy - cy
        m = (x / (55 * s)) ** 2 + (y / (50 * s)) ** 2 <= 1.0  # palm
        for k, (dx, top) in enumerate([(-39, -115), (-13, -135), (13, -130), (39, -105)]):
            m |= (np.abs(x - dx * s) <= 9 * s) & (y >= top * s) & (y <= -20 * s)  # fingers
        # thumb: a thick segment from the palm's side, pointing down-left
        ax, ay, bx, by = -45 * s, 10 * s, -95 * s, -35 * s
        px, py = x - ax, y - ay
        vx, vy = bx - ax, by - ay
        u = np.clip((px * vx + py * vy) / (vx * vx + vy * vy), 0, 1)
        m |= (px - u * vx) ** 2 + (py - u * vy) ** 2 <= (11 * s) ** 2
        return m

    def frame(self, mask):
        """RGBx: 4 bytes a pixel, so rows need no padding at any width."""
        img = self.background.copy()
        img[mask] = (205, 160, 130)  # an evenly coloured object, as the paper assumes
        img += self.rng.normal(0, 4, img.shape)
        rgbx = np.zeros((self.h, self.w, 4), np.uint8)
        rgbx[..., :3] = np.clip(img, 0, 255)
        return rgbx


def truth(mask):
    ys, xs = np.nonzero(mask)
    return xs.mean(), ys.mean(), float(len(xs))


TRACKING = {'ok', 'reached-border', 'covers-frame'}
OPENCV_DOC = '/usr/share/doc/opencv-doc/opencv4/html'
TRUTH = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'bench', 'real', 'truth')


def collect(pipeline, truths):
    """The projtrack messages of a running pipeline until EOS, one row a frame, with the truth."""
    bus = pipeline.get_bus()
    rows, error = [], None
    while True:
        msg = bus.timed_pop_filtered(Gst.CLOCK_TIME_NONE, Gst.MessageType.ELEMENT |
                                     Gst.MessageType.EOS | Gst.MessageType.ERROR)
        if msg.type == Gst.MessageType.ERROR:
            error = msg.parse_error()[0].message
            break
        if msg.type == Gst.MessageType.EOS:
            break
        s = msg.get_structure()
        if s is None or s.get_name() != 'projtrack':
            continue
        i = len(rows)
        tx, ty, ta = truths[i] if i < len(truths) else (float('nan'),) * 3
        row = {'frame': i, 'timestamp_s': s.get_value('timestamp') / Gst.SECOND,
               'status': s.get_string('status'),
               'processing_ms': s.get_value('processing-time') / 1e6,
               'true_centroid_x': round(tx, 2), 'true_centroid_y': round(ty, 2), 'true_area': ta}
        # A lost track's message holds the last accepted features: not a measurement.
        if row['status'] in TRACKING:
            for f in ['centroid-x', 'centroid-y', 'area', 'x', 'y', 'width', 'height',
                      'inner-point-x', 'inner-point-y', 'iterations']:
                row[f.replace('-', '_')] = s.get_value(f)
        rows.append(row)
    pipeline.set_state(Gst.State.NULL)
    return rows, error


def report(rows, title, video, table):
    """Writes the CSV, prints the summary; returns the number of frames tracked."""
    with open(table, 'w', newline='') as f:
        w = csv.DictWriter(f, FIELDS)
        w.writeheader()
        w.writerows(rows)
    tracked = [r for r in rows if 'area' in r]
    errs = [math.hypot(r['centroid_x'] - r['true_centroid_x'], r['centroid_y'] - r['true_centroid_y'])
            for r in tracked]
    area = [abs(r['area'] / r['true_area'] - 1) for r in tracked]
    ms = sorted(r['processing_ms'] for r in rows)
    print(title)
    print(f'  tracked        {len(tracked)}/{len(rows)} frames')
    if tracked:
        print(f'  centroid error mean {np.mean(errs):.2f} px, max {max(errs):.2f} px')
        print(f'  area error     mean {100 * np.mean(area):.1f} %, max {100 * max(area):.1f} %')
    print(f'  time per frame median {ms[len(ms) // 2]:.2f} ms (the whole frame in the element: model, estimate, overlay)')
    print(f'  wrote {video} and {table}')
    return len(tracked)


def real_clip(args):
    """A real held object: opencv-doc's clip, seeded where the truth's first silhouette is
    deepest, scored against that truth."""
    path = os.path.join(args.out, args.clip + '.mp4')
    packed = os.path.join(OPENCV_DOC, args.clip + '.mp4.gz')
    if not os.path.exists(packed):
        raise Failure(f'no {packed}: install opencv-doc (and gstreamer1.0-libav to decode it)',
                      USAGE)
    with gzip.open(packed) as src, open(path, 'wb') as dst:
        dst.write(src.read())
    with open(os.path.join(TRUTH, args.clip + '.csv'), newline='') as f:
        truth_rows = list(csv.DictReader(f))
    truths = [(float(r['centroid_x']), float(r['centroid_y']), float(r['area'])) for r in truth_rows]
    seed = (int(truth_rows[0]['inner_x']), int(truth_rows[0]['inner_y']))
    video = os.path.join(args.out, args.clip + '.webm')
    pipeline = parse_launch(
        Gst, f'filesrc location={path} ! decodebin ! videoconvert ! '
        f'projtrack name=tracker draw=true method={args.method} {args.extra} '
        f'inner-point-x={seed[0]} inner-point-y={seed[1]} ! '
        f'videoconvert ! vp8enc deadline=1 cpu-used=8 ! webmmux ! filesink location={video}')
    pipeline.set_state(Gst.State.PLAYING)
    rows, error = collect(pipeline, truths)
    if error or not rows:
        raise Failure(f'pipeline error: {error or "no projtrack message arrived"}')
    tracked = report(rows, f'projtrack demo: {args.method}, opencv-doc {args.clip}.mp4, '
                     f'{len(rows)} frames, seeded at {seed[0]},{seed[1]}',
                     video, os.path.join(args.out, args.clip + '.csv'))
    return 0 if tracked else FAILED


def main():
    ap = parser(__doc__)
    ap.add_argument('--clip', choices=['cup', 'box'],
                    help="a real clip of opencv-doc's instead of the generated video")
    ap.add_argument('--out', default='out', help='where to write (default out)')
    ap.add_argument('--frames', type=positive_int, default=300, help='frames to generate')
    ap.add_argument('--width', type=positive_int, default=640, help='frame width')
    ap.add_argument('--height', type=positive_int, default=480, help='frame height')
    ap.add_argument('--method', default='gap-tolerant-filling', help='projtrack\'s method')
    ap.add_argument('--extra', default='', help='more projtrack properties, e.g. "grid-size=12"')
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    gstreamer()
    if args.clip:
        return real_clip(args)
    scene = HandScene(args.width, args.height)
    cx, cy, _ = scene.pose(0)
    video = os.path.join(args.out, 'demo.webm')
    pipeline = parse_launch(
        Gst, f'appsrc name=src is-live=false format=time '
        f'caps=video/x-raw,format=RGBx,width={args.width},height={args.height},framerate=30/1 ! '
        f'videoconvert ! projtrack name=tracker draw=true method={args.method} {args.extra} '
        f'inner-point-x={int(cx)} inner-point-y={int(cy)} ! '
        f'videoconvert ! vp8enc deadline=1 cpu-used=8 ! webmmux ! filesink location={video}')
    src = pipeline.get_by_name('src')
    pipeline.set_state(Gst.State.PLAYING)

    truths = []
    for i in range(args.frames):
        m = scene.mask(i)
        truths.append(truth(m))
        buf = Gst.Buffer.new_wrapped(scene.frame(m).tobytes())
        buf.pts = i * Gst.SECOND // 30
        buf.duration = Gst.SECOND // 30
        if src.emit('push-buffer', buf) != Gst.FlowReturn.OK:
            break
    src.emit('end-of-stream')

    rows, error = collect(pipeline, truths)
    if error or not rows:
        raise Failure(f'pipeline error: {error or "no projtrack message arrived"}')
    tracked = report(rows, f'projtrack demo: {args.method}, {args.width}x{args.height}, '
                     f'{len(rows)} frames', video, os.path.join(args.out, 'demo.csv'))
    return 0 if tracked == len(rows) else FAILED


if __name__ == '__main__':
    run('demo', main)
