#!/usr/bin/python3
"""Several objects at once with projtrack.MultiTracker: each followed with its own id, one line per
frame for each.

    PYTHONPATH=build/python examples/track_several.py          # opencv-doc's cup and the hand
    PYTHONPATH=build/python examples/track_several.py --picture cup-and-hand.png
    PYTHONPATH=build/python examples/track_several.py --video clip.mp4 --point 100,80 --box 300,60,80,120

By default the cup of opencv-doc's cup clip and the hand that holds it, each started from a point
inside it: followed together, each object keeps its own pixels (followed alone from a box, the
cup takes the fingers and then the hand: docs/tracker.md#limits). --point and --box add an object
each (repeat them). --picture writes a row of frames (--picture-frames) with each object's
outline in its own colour and its id. Needs the module projtrack (PYTHONPATH=build/python) and
Debian's python3-opencv; the cup clip needs opencv-doc. Exit code 0 when every object was measured
on a frame, 1 when one never was, 2 for a bad option or a missing clip, video or package.
"""
import gzip
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli import USAGE, Failure, module, parser, positive_int, run, say  # noqa: E402
from track_numpy import CLIPS, numbers, video_frames  # noqa: E402

cv2 = module('track_several', 'cv2', 'python3-opencv')
np = module('track_several', 'numpy', 'python3-numpy')
projtrack = module('track_several', 'projtrack', None,
                   'build it (./run build) and set PYTHONPATH=build/python, or install it '
                   '(meson install)')

CUP_AND_HAND = [('point', (360, 170)), ('point', (520, 230))]  # the cup, the hand (frame 0)
COLOURS = [(0, 200, 255), (255, 120, 0), (80, 220, 80), (200, 80, 255), (0, 0, 230)]


def cup_frames(limit, workdir):
    packed = os.path.join(CLIPS, 'cup.mp4.gz')
    if not os.path.exists(packed):
        raise Failure(f'no {packed}: install opencv-doc, or use --video', USAGE)
    path = os.path.join(workdir, 'cup.mp4')
    with gzip.open(packed) as src, open(path, 'wb') as dst:
        dst.write(src.read())
    return video_frames(path, limit)


def drawn(frame, tracker, results):
    """The frame with each object's outline in its colour and its id beside it."""
    picture = frame.copy()
    for n, (id, r) in enumerate(results.items()):
        colour = COLOURS[n % len(COLOURS)]
        mask = tracker.mask(id)
        if mask is not None:
            outlines, _ = cv2.findContours((mask > 0).astype(np.uint8), cv2.RETR_EXTERNAL,
                                           cv2.CHAIN_APPROX_SIMPLE)
            cv2.drawContours(picture, outlines, -1, colour, 3)
        if r.ok:
            x, y = r.box[:2]
            cv2.putText(picture, f'{id} {r.status}', (x, max(y - 8, 16)),
                        cv2.FONT_HERSHEY_SIMPLEX, 0.8, colour, 2)
    return picture


def main():
    ap = parser(__doc__)
    ap.add_argument('--video', help='a video file (with --point or --box)')
    ap.add_argument('--point', type=numbers(2), action='append', default=[],
                    help='x,y inside an object on frame 0 (repeat for more)')
    ap.add_argument('--box', type=numbers(4), action='append', default=[],
                    help='x,y,w,h around an object on frame 0 (repeat for more)')
    ap.add_argument('--frames', type=positive_int, default=1000, help='at most this many frames')
    ap.add_argument('--quiet', action='store_true', help='print the summary alone')
    ap.add_argument('--picture', help='write a row of frames with the objects drawn to this image')
    ap.add_argument('--picture-frames', type=numbers(3), default=(0, 60, 120),
                    help='the three frames --picture shows (default 0,60,120)')
    args = ap.parse_args()
    starts = [('point', p) for p in args.point] + [('box', b) for b in args.box]
    if args.video and not starts:
        ap.error('--video needs --point or --box')
    with tempfile.TemporaryDirectory() as workdir:
        frames = video_frames(args.video, args.frames) if args.video else cup_frames(args.frames,
                                                                                     workdir)
        return follow(args, frames, starts or CUP_AND_HAND)


def follow(args, frames, starts):
    """Follows every start over `frames`, a line per frame and object, then a summary."""
    tracker = projtrack.MultiTracker()
    measured, shown, count = {}, [], 0
    for i, frame in enumerate(frames):
        if i == 0:
            for kind, where in starts:
                try:
                    measured[tracker.add(frame, **{kind: where})] = 0
                except ValueError as e:  # outside the frame, or on an object added already
                    raise Failure(f'frame 0: {kind} {where}: {e}', USAGE) from None
        results = tracker.track(frame)
        for id, r in results.items():
            measured[id] += r.ok
            area = f'area {r.area:6.0f} px²' if r.ok else r.detail[:50]
            if not args.quiet and not say(f'{i:5}  object {id}  {r.status:14} {area}'):
                return 0
        if i in args.picture_frames:
            shown.append(drawn(frame, tracker, results))
        count = i + 1
    if not count:
        raise Failure('the video has no frames')
    for id, n in measured.items():
        say(f'object {id}: measured on {n} of {count} frames')
    if args.picture:
        if not shown:
            raise Failure(f'none of frames {args.picture_frames} is in the video', USAGE)
        row = np.hstack([cv2.resize(p, (p.shape[1] // 2, p.shape[0] // 2)) for p in shown])
        if not cv2.imwrite(args.picture, row, [cv2.IMWRITE_PNG_COMPRESSION, 9]):
            raise Failure(f'cannot write {args.picture}')
    return 0 if all(measured.values()) else 1


if __name__ == '__main__':
    run('track_several', main)
