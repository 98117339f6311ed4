#!/usr/bin/python3
"""Runs the examples and the demo as a user would, and checks what they print and write.

    test_examples.py c BINARY | python SCRIPT | roi SCRIPT | demo SCRIPT OUTDIR |
                     cursor SCRIPT OUTDIR | pointer SCRIPT | recipes CURSOR_SCRIPT OUTDIR
"""
import csv
import os
import re
import subprocess
import sys

LINE = re.compile(r'\s(ok|reached-border)\s+centroid \(\s*([\d.]+),\s*([\d.]+)\)\s+area\s+(\d+)')


def check_feature_lines(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True, timeout=120, check=True).stdout
    lines = out.splitlines()
    found = [LINE.search(line) for line in lines]
    assert len(lines) == 60, f'expected one line per frame (60), got {len(lines)}:\n{out}'
    assert all(found), f'a frame without features:\n{out}'
    # videotestsrc's ball starts at the frame centre with radius ~19: area ~ pi * 18^2.
    x, y, area = float(found[0][2]), float(found[0][3]), float(found[0][4])
    assert abs(x - 160) < 2 and abs(y - 120) < 2, (x, y)
    assert 800 < area < 1300, area


def check_demo(script, out_dir):
    subprocess.run([script, '--frames', '40', '--out', out_dir], timeout=300, check=True)
    with open(os.path.join(out_dir, 'demo.csv')) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 40, len(rows)
    # Tracked on every frame with a sane estimate: the centroid within 6 % of the object's size
    # (sqrt(area)) of the truth, the area within 20 %, at the element's defaults.
    for r in rows:
        assert r['status'] == 'ok', r
        err = ((float(r['centroid_x']) - float(r['true_centroid_x'])) ** 2 +
               (float(r['centroid_y']) - float(r['true_centroid_y'])) ** 2) ** 0.5
        assert err < 0.06 * float(r['true_area']) ** 0.5, r
        assert abs(float(r['area']) / float(r['true_area']) - 1) < 0.20, r
    assert os.path.getsize(os.path.join(out_dir, 'demo.webm')) > 10000


def check_held_features_are_not_measurements(script):
    """A 'lost' message repeats the last features: print_features.py must not print them."""
    sys.path.insert(0, os.path.dirname(script))
    import gi
    gi.require_version('Gst', '1.0')
    from gi.repository import Gst
    Gst.init(None)
    from print_features import describe
    held = Gst.Structure.from_string(
        'projtrack, status=lost, detail="the estimate leaked", centroid-x=1.0, centroid-y=2.0, '
        'area=300.0, width=10, height=10, timestamp=(guint64)0, processing-time=(guint64)0')[0]
    line = describe(held)
    assert 'lost' in line and 'the estimate leaked' in line and 'centroid' not in line, line


def check_roi(script):
    """The ROI meta read from a pad probe and from an appsink: one line per buffer."""
    for mode in ([], ['--appsink']):
        out = subprocess.run([script] + mode, capture_output=True, text=True, timeout=120,
                             check=True).stdout
        lines = out.splitlines()
        assert len(lines) == 60, f'{mode}: one line per buffer (60), got {len(lines)}:\n{out}'
        first = re.search(r'ok\s+box (\d+),(\d+) (\d+)x(\d+)\s+centroid \(\s*([\d.]+),\s*([\d.]+)\)',
                          lines[0])
        assert first, lines[0]
        x, y, w, h, cx, cy = (float(v) for v in first.groups())
        assert x <= cx <= x + w and y <= cy <= y + h, first.groups()  # the box holds the centroid
        assert abs(cx - 160) < 2 and abs(cy - 120) < 2 and 30 < w < 45, first.groups()
    out = subprocess.run(
        [script, '--pipeline', 'videotestsrc num-buffers=3 ! projtrack name=tracker '
         'acquisition=manual ! fakesink'], capture_output=True, text=True, timeout=60,
        check=True).stdout
    assert out.count('no meta') == 3, out  # nothing tracked: no meta, and the reader says so


def check_cursor(script, out_dir):
    png = os.path.join(out_dir, 'trajectory.png')
    table = os.path.join(out_dir, 'trajectory.csv')
    out = subprocess.run([script, '--generated', '--frames', '100', '--out', png, '--csv', table,
                          '--live'], capture_output=True, text=True, timeout=300, check=True).stdout
    lines = re.split(r'[\r\n]', out)
    assert any('acquired an object' in line for line in lines), out
    assert sum(' push ' in line for line in lines) == 1, out
    live = [line for line in lines if re.search(r'x [-+]\d\.\d\d  y [-+]\d\.\d\d  depth \d', line)]
    assert len(live) > 50, f'a live x/y/depth line per tracked frame: {len(live)}'
    assert os.path.getsize(png) > 10000
    with open(table) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 100, len(rows)  # every frame
    tracked = [r for r in rows if r['status'] in ('ok', 'reached-border', 'covers-frame')]
    assert len(tracked) > 50 and all(r['x'] and r['depth'] and r['area'] for r in tracked)
    assert all(not r['x'] for r in rows if r not in tracked), 'features only when measured'
    assert sum(r['gesture'] == 'push' for r in rows) == 1
    # No camera: a clear message and exit code 2, never a crash.
    none = subprocess.run([script, '--camera', os.path.join(out_dir, 'no-such-camera')],
                          capture_output=True, text=True, timeout=60)
    assert none.returncode == 2 and 'no camera at' in none.stderr, (none.returncode, none.stderr)


def check_pointer(script):
    """The uinput pointer's dry run on the generated hand: the events it would send."""
    out = subprocess.run([script, '--dry-run', '--generated', '--frames', '100'],
                         capture_output=True, text=True, timeout=300, check=True).stdout
    events = [line.split() for line in out.splitlines()]
    xs = [int(e[2]) for e in events if e[:2] == ['EV_ABS', 'ABS_X']]
    ys = [int(e[2]) for e in events if e[:2] == ['EV_ABS', 'ABS_Y']]
    assert len(xs) > 50 and len(xs) == len(ys), (len(xs), len(ys))
    assert all(0 <= v <= 65535 for v in xs + ys)
    assert xs[-1] > xs[0] + 2000, (xs[0], xs[-1])  # the hand drifts right, unmirrored
    clicks = [e for e in events if e[:2] == ['EV_KEY', 'BTN_LEFT']]
    assert [e[2] for e in clicks] == ['1', '0'], clicks  # one push: one press and release
    assert out.count('SYN_REPORT') == len(xs) + 2
    check_pointer_drag(script)


def drag_clip(path):
    """A WebM file of an orange disc on grey that moves right, is pushed toward the camera and
    held there while it moves on (a drag), comes back, then clicks once."""
    import math
    import gi
    gi.require_version('Gst', '1.0')
    from gi.repository import Gst
    import numpy as np
    Gst.init(None)
    pipeline = Gst.parse_launch(
        'appsrc name=src format=time caps=video/x-raw,format=RGB,width=320,height=240,'
        'framerate=30/1 ! videoconvert ! vp8enc deadline=1 ! webmmux ! filesink '
        f'location={path}')
    src = pipeline.get_by_name('src')
    pipeline.set_state(Gst.State.PLAYING)
    rng = np.random.default_rng(3)
    yy, xx = np.mgrid[0:240, 0:320]
    for i in range(180):
        t = i / 30
        # forward at 1.5 s (+30 % over 0.2 s), held 1.4 s, back; a 0.3 s click at 4.5 s
        held = min(max((t - 1.5) / 0.2, 0), 1) * (t < 3.1) + (3.1 <= t < 3.3) * (3.3 - t) / 0.2
        scale = 1 + 0.3 * (1 - math.cos(math.pi * held)) / 2
        if 4.5 < t < 4.8:
            scale += 0.3 * (1 - math.cos(2 * math.pi * (t - 4.5) / 0.3)) / 2
        cx, r = 90 + 30 * t, 30 * scale
        img = rng.integers(100, 130, (240, 320, 3), dtype=np.uint8)
        img[(xx - cx) ** 2 + (yy - 120) ** 2 <= r * r] = (230, 120, 30)
        buf = Gst.Buffer.new_wrapped(img.tobytes())
        buf.pts, buf.duration = i * Gst.SECOND // 30, Gst.SECOND // 30
        src.emit('push-buffer', buf)
    src.emit('end-of-stream')
    pipeline.get_bus().timed_pop_filtered(60 * Gst.SECOND, Gst.MessageType.EOS |
                                          Gst.MessageType.ERROR)
    pipeline.set_state(Gst.State.NULL)


def check_pointer_drag(script):
    """The dry run on a clip with a drag and a click: the button goes down when the object is
    pushed and held, stays down while the pointer moves, comes up when it is back; then one
    click (down and up at once)."""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        clip = os.path.join(tmp, 'drag.webm')
        drag_clip(clip)
        out = subprocess.run([script, '--dry-run', '--file', clip], capture_output=True,
                             text=True, timeout=300, check=True).stdout
    events = [line.split() for line in out.splitlines()]
    button = [(i, e[2]) for i, e in enumerate(events) if e[:2] == ['EV_KEY', 'BTN_LEFT']]
    assert [v for _, v in button] == ['1', '0', '1', '0'], button
    (down, _), (up, _) = button[:2]
    moved = [int(e[2]) for e in events[down:up] if e[:2] == ['EV_ABS', 'ABS_X']]
    assert len(moved) > 20 and moved[-1] > moved[0] + 2000, moved  # dragged right while down
    assert button[3][0] - button[2][0] == 2, button  # the click: down, SYN_REPORT, up



def check_recipes(cursor_script, out_dir):
    """The recipes of docs/element.md, with videotestsrc where they use a camera: record the overlay to a
    WebM file; run cursor3d.py on a file for a CSV of every frame."""
    os.makedirs(out_dir, exist_ok=True)
    tracked = os.path.join(out_dir, 'tracked.webm')
    subprocess.run(['gst-launch-1.0', '-q', '-e', 'videotestsrc', 'pattern=ball', 'num-buffers=45',
                    '!', 'video/x-raw,width=640,height=480', '!', 'videoconvert', '!', 'projtrack',
                    'draw=true', '!', 'videoconvert', '!', 'vp8enc', 'deadline=1', '!', 'webmmux',
                    '!', 'filesink', f'location={tracked}'], check=True, timeout=120)
    assert os.path.getsize(tracked) > 5000, os.path.getsize(tracked)
    # A clip without the overlay (the overlay's changing text is motion of its own).
    clip = os.path.join(out_dir, 'clip.webm')
    subprocess.run(['gst-launch-1.0', '-q', '-e', 'videotestsrc', 'pattern=ball', 'num-buffers=45',
                    '!', 'video/x-raw,width=640,height=480', '!', 'videoconvert', '!', 'vp8enc',
                    'deadline=1', '!', 'webmmux', '!', 'filesink', f'location={clip}'],
                   check=True, timeout=120)
    table = os.path.join(out_dir, 'clip.csv')
    subprocess.run([cursor_script, '--file', clip, '--csv', table,
                    '--out', os.path.join(out_dir, 'clip.png')], check=True, timeout=120,
                   capture_output=True)
    with open(table) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 45, len(rows)  # every frame of the file
    assert sum(r['status'] == 'ok' and r['x'] != '' for r in rows) > 30, rows


kind = sys.argv[1]
if kind in ('c', 'python'):
    check_feature_lines([sys.argv[2]])
    if kind == 'python':
        check_held_features_are_not_measurements(sys.argv[2])
elif kind == 'roi':
    check_roi(sys.argv[2])
elif kind == 'pointer':
    check_pointer(sys.argv[2])
elif kind == 'recipes':
    check_recipes(sys.argv[2], sys.argv[3])
elif kind == 'demo':
    check_demo(sys.argv[2], sys.argv[3])
elif kind == 'cursor':
    check_cursor(sys.argv[2], sys.argv[3])
else:
    sys.exit(f'unknown kind {kind}')
print(f'{kind}: ok')
