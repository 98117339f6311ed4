#!/usr/bin/python3
"""projtrack beside OpenCV's tracker API: the same numpy frames into projtrack's Python tracker
and into one of OpenCV's (KCF, CSRT or MIL), one line per frame for each.

    PYTHONPATH=build/python examples/track_numpy.py                    # opencv-doc's cup, KCF
    PYTHONPATH=build/python examples/track_numpy.py --opencv csrt --frames 100
    PYTHONPATH=build/python examples/track_numpy.py --video clip.mp4 --box 280,200,80,80
    PYTHONPATH=build/python examples/track_numpy.py --generated        # a generated hand

Both start from the same box: the clip's first true box (bench/real/truth/), the generated hand's, or
--box. From --point (inside the object) projtrack starts alone and OpenCV's tracker from the
box projtrack measured on the first frame. projtrack.Tracker offers OpenCV's pair too
(tracker.init(frame, box), ok, box = tracker.update(frame)); this example calls track(), which
also gives the area, the status and the silhouette. --picture writes a frame with both boxes
and projtrack's silhouette. Needs the module projtrack (PYTHONPATH=build/python) and Debian's
python3-opencv; the clips need opencv-doc. Exit code 0 when projtrack measured the object on a
frame, 1 when it never did, 2 for a bad option or a missing clip, video or package.
"""
import csv
import gzip
import os
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli import USAGE, Failure, module, parser, positive_int, run, say  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CLIPS = '/usr/share/doc/opencv-doc/opencv4/html'
TRUTH = os.path.join(HERE, '..', 'bench', 'real', 'truth')
OPENCV = {'kcf': 'TrackerKCF_create', 'csrt': 'TrackerCSRT_create', 'mil': 'TrackerMIL_create'}

cv2 = module('track_numpy', 'cv2', 'python3-opencv')
np = module('track_numpy', 'numpy', 'python3-numpy')
projtrack = module('track_numpy', 'projtrack', None,
                   'build it (./run build) and set PYTHONPATH=build/python, or install it '
                   '(meson install)')


def numbers(count):
    """An argparse type: `count` integers separated by commas."""
    def parse(text):
        try:
            values = tuple(int(v) for v in text.split(','))
        except ValueError:
            values = ()
        if len(values) != count:
            raise ValueError
        return values
    parse.__name__ = f'{count} integers x,y' + (',w,h' if count == 4 else '')
    return parse


def video_frames(path, limit):
    """The frames of a video file (BGR, as cv2.VideoCapture reads them), at most `limit`; a
    Failure at once when it cannot be read."""
    if not os.path.isfile(path):
        raise Failure(f'no file {path}', USAGE)
    capture = cv2.VideoCapture(path, cv2.CAP_FFMPEG)
    if not capture.isOpened():
        raise Failure(f'cannot read the video {path}', USAGE)

    def frames():
        try:
            for _ in range(limit):
                ok, frame = capture.read()
                if not ok:
                    return
                yield frame
        finally:
            capture.release()
    return frames()


def clip_source(name, limit, workdir):
    """opencv-doc's clip `name`, gunzipped into `workdir`, and its first true box."""
    packed = os.path.join(CLIPS, f'{name}.mp4.gz')
    if not os.path.exists(packed):
        raise Failure(f'no {packed}: install opencv-doc, or use --video or --generated', USAGE)
    path = os.path.join(workdir, f'{name}.mp4')
    with gzip.open(packed) as src, open(path, 'wb') as dst:
        dst.write(src.read())
    with open(os.path.join(TRUTH, f'{name}.csv'), newline='') as f:
        first = next(csv.DictReader(f))
    box = tuple(int(first[k]) for k in ('x', 'y', 'width', 'height'))
    return video_frames(path, limit), box


def generated_source(limit):
    """The demo's generated hand as BGR frames, and its first box."""
    from demo import HandScene
    scene = HandScene(640, 480)
    ys, xs = np.nonzero(scene.mask(0))
    box = (int(xs.min()), int(ys.min()), int(xs.max() - xs.min() + 1), int(ys.max() - ys.min() + 1))
    frames = (np.ascontiguousarray(scene.frame(scene.mask(i))[..., 2::-1]) for i in range(limit))
    return frames, box


def box_text(box):
    x, y, w, h = (int(round(v)) for v in box)
    return f'box {x},{y} {w}x{h}'


def projtrack_text(r):
    """One frame of projtrack: its box and area when measured, else the status and why."""
    if r.ok:
        return f'{r.status:14} {box_text(r.box):22} area {r.area:6.0f} px²'
    return f'{r.status:14} {r.detail[:44]:44}'


def draw(frame, result, opencv_box, name):
    """The frame with projtrack's silhouette tinted and box (green) and OpenCV's box (blue)."""
    picture = frame.copy()
    if result.mask is not None:
        tint = picture.copy()
        tint[result.mask > 0] = (0, 200, 255)
        picture = cv2.addWeighted(picture, 0.6, tint, 0.4, 0)
    if result.ok:
        x, y, w, h = result.box
        cv2.rectangle(picture, (x, y), (x + w - 1, y + h - 1), (0, 220, 0), 2)
        cv2.putText(picture, 'projtrack', (x, y - 6), cv2.FONT_HERSHEY_SIMPLEX, 0.6,
                    (0, 220, 0), 2)
    if opencv_box:
        x, y, w, h = (int(round(v)) for v in opencv_box)
        cv2.rectangle(picture, (x, y), (x + w - 1, y + h - 1), (255, 80, 0), 2)
        cv2.putText(picture, name, (x, y + h + 18), cv2.FONT_HERSHEY_SIMPLEX, 0.6,
                    (255, 80, 0), 2)
    return picture


def main():
    ap = parser(__doc__)
    src = ap.add_mutually_exclusive_group()
    src.add_argument('--clip', choices=['cup', 'box'], default='cup',
                     help="one of opencv-doc's clips (default cup)")
    src.add_argument('--video', help='a video file (with --box or --point)')
    src.add_argument('--generated', action='store_true', help='a generated hand')
    start = ap.add_mutually_exclusive_group()
    start.add_argument('--box', type=numbers(4), help='x,y,w,h around the object on frame 0')
    start.add_argument('--point', type=numbers(2), help='x,y inside the object on frame 0')
    ap.add_argument('--opencv', choices=[*OPENCV, 'none'], default='kcf',
                    help="OpenCV's tracker beside projtrack (default kcf)")
    ap.add_argument('--method', default='gap-tolerant-filling',
                    help=f'projtrack\'s method: {", ".join(projtrack.methods())}')
    ap.add_argument('--frames', type=positive_int, default=1000, help='at most this many frames')
    ap.add_argument('--picture', help='write a frame with both boxes drawn to this image')
    ap.add_argument('--picture-frame', type=int, default=-1,
                    help='the frame --picture shows (default the last)')
    args = ap.parse_args()
    if args.video and not (args.box or args.point):
        ap.error('--video needs --box or --point')
    try:
        tracker = projtrack.Tracker(method=args.method)
    except ValueError as e:
        raise Failure(str(e), USAGE) from None
    with tempfile.TemporaryDirectory() as workdir:
        if args.video:
            frames, box = video_frames(args.video, args.frames), None
        elif args.generated:
            frames, box = generated_source(args.frames)
        else:
            frames, box = clip_source(args.clip, args.frames, workdir)
        return compare(args, tracker, frames, args.box or (None if args.point else box))


def compare(args, tracker, frames, box):
    """Runs both trackers over `frames`, printing a line per frame and a summary."""
    name = args.opencv.upper()
    opencv = None
    times = {'projtrack': [], name: []}
    measured = found = 0
    header = f'{"frame":>5}  {"projtrack (" + args.method + ")":60}  OpenCV {name}'
    for i, frame in enumerate(frames):
        t0 = time.perf_counter()
        try:
            r = tracker.track(frame, box=box, point=args.point) if i == 0 else tracker.track(frame)
        except ValueError as e:  # the start lies outside the video's frame
            raise Failure(f'frame 0: {e}', USAGE) from None
        times['projtrack'].append(time.perf_counter() - t0)
        measured += r.ok
        opencv_box = None
        if i == 0 and args.opencv != 'none' and (box or r.ok):
            opencv = getattr(cv2, OPENCV[args.opencv])()
            opencv_box = tuple(box or r.box)
            t0 = time.perf_counter()
            opencv.init(frame, opencv_box)
            times[name].append(time.perf_counter() - t0)
            ok = True
        elif opencv:
            t0 = time.perf_counter()
            ok, opencv_box = opencv.update(frame)
            times[name].append(time.perf_counter() - t0)
        else:
            ok = False
        found += bool(ok)
        theirs = f'{"ok" if ok else "lost":5} {box_text(opencv_box)}' if ok else 'lost'
        if (i == 0 and not say(header)) or not say(
                f'{i:5}  {projtrack_text(r):60}  {theirs if opencv else "-"}'):
            return 0
        if i == args.picture_frame or args.picture_frame < 0:
            shown = (frame, r, opencv_box if ok else None)
    if not times['projtrack']:
        raise Failure('the video has no frames')
    summary = [('projtrack (' + args.method + ')', measured, times['projtrack'])]
    if opencv:
        summary.append((f'OpenCV {name}', found, times[name]))
    for who, count, spent in summary:
        say(f'{who}: the object on {count} of {len(times["projtrack"])} frames, median '
            f'{1000 * statistics.median(spent):.1f} ms a frame')
    if args.picture and not cv2.imwrite(args.picture, draw(*shown, f'OpenCV {name}'),
                                        [cv2.IMWRITE_PNG_COMPRESSION, 9]):
        raise Failure(f'cannot write {args.picture}')
    return 0 if measured else 1


if __name__ == '__main__':
    run('track_numpy', main)
