#!/usr/bin/python3
"""The element and the Python module give the same answers on the same frames (issue 32, item 2):
opencv-doc's cup, decoded once with OpenCV, through `appsrc ! projtrack ! fakesink` (caps BGR,
then GRAY8 or another size, as a source renegotiating) and through projtrack.Tracker (BGR numpy
frames, then gray ones or another size), both started from the same box on the first frame. Every
frame's status, centroid and area are compared, through a size change (640x480 -> 320x240 at
frame 20), a format change (BGR -> gray at frame 20) and a clip joined to itself at half its size
after all its frames (the picture jumps back as the size changes: the cup is where it was on frame
0), and two objects (the cup from its box, the hand from a point) through the element's
start-boxes and start-points and a MultiTracker, compared by id. Exit status 77 (skipped) without the clip
(opencv-doc) or the element."""
import gzip
import os
import shutil
import sys
import tempfile

import cv2
import gi
import numpy as np

import projtrack

gi.require_version('Gst', '1.0')
from gi.repository import Gst  # noqa: E402

CUP = '/usr/share/doc/opencv-doc/opencv4/html/cup.mp4.gz'
BOX = (308, 126, 104, 256)  # the cup on frame 0 at 640x480 (a user's box)
FRAMES = 60
CHANGE = 20
FPS = 30
# In gray the cup joins the arm that holds it from frame 42 on, however the track started
# (measured: after 20 or 40 colour frames; the hand and the dark sleeve have the cup's luma and
# move with it): the track after the format change is judged before that.
GRAY_HOLDS = 42
JOINED = 30
HAND = (520, 230)  # a point on the hand that holds the cup, frame 0 at 640x480


def cup_frames(n):
    """The clip's first n frames, BGR, as cv2.VideoCapture decodes them."""
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, 'cup.mp4')
        with gzip.open(CUP) as src, open(path, 'wb') as dst:
            shutil.copyfileobj(src, dst)
        cap = cv2.VideoCapture(path)
        frames = []
        while len(frames) < n:
            ok, f = cap.read()
            if not ok:
                break
            frames.append(f)
    return frames


def half(f):
    return cv2.resize(f, (f.shape[1] // 2, f.shape[0] // 2), interpolation=cv2.INTER_AREA)


def scenario(frames, change):
    """The frames each side is given: (numpy frame, GStreamer format), `change` from CHANGE on
    (for 'joined': the frames, then their first JOINED halved)."""
    if change == 'joined':
        return [(np.ascontiguousarray(f), 'BGR') for f in frames] + \
            [(np.ascontiguousarray(half(f)), 'BGR') for f in frames[:JOINED]]
    out = []
    for i, f in enumerate(frames):
        if i >= CHANGE and change == 'size':
            f = half(f)
        if i >= CHANGE and change == 'format':
            out.append((np.ascontiguousarray(cv2.cvtColor(f, cv2.COLOR_BGR2GRAY)), 'GRAY8'))
        else:
            out.append((np.ascontiguousarray(f), 'BGR'))
    return out


def run_python(frames):
    t = projtrack.Tracker()
    rows = []
    for i, (f, _) in enumerate(frames):
        r = t.track(f, box=BOX, mask=False) if i == 0 else t.track(f, mask=False)
        rows.append((r.status, r.centroid, r.area))
    return rows


def run_element(frames, props=None, by_id=False):
    """Every frame's (status, centroid, area) from the element's messages; `props`: its
    properties (default: acquisition=manual and BOX as the start box, as Python's init());
    `by_id`: {id: rows}, from the messages' `id` (0 without one)."""
    if props is None:
        props = 'acquisition=manual start-box="<{},{},{},{}>"'.format(*BOX)
    pipeline = Gst.parse_launch(f'appsrc name=src format=time ! projtrack name=t {props} ! '
                                'fakesink sync=false')
    src = pipeline.get_by_name('src')
    bus = pipeline.get_bus()
    pipeline.set_state(Gst.State.PLAYING)
    caps = None
    for i, (f, fmt) in enumerate(frames):
        h = f.shape[0] * 2 // 3 if fmt == 'I420' else f.shape[0]  # I420: its planes' rows
        c = f'video/x-raw,format={fmt},width={f.shape[1]},height={h},framerate={FPS}/1'
        if c != caps:  # appsrc sends the new caps in the stream, before the next buffer
            src.set_property('caps', Gst.Caps.from_string(c))
            caps = c
        buf = Gst.Buffer.new_wrapped(f.tobytes())
        buf.pts = i * Gst.SECOND // FPS
        buf.duration = Gst.SECOND // FPS
        src.emit('push-buffer', buf)
    src.emit('end-of-stream')
    rows = []
    while True:
        m = bus.timed_pop_filtered(60 * Gst.SECOND, Gst.MessageType.ELEMENT | Gst.MessageType.EOS |
                                   Gst.MessageType.ERROR)
        if m is None or m.type != Gst.MessageType.ELEMENT:
            if m is not None and m.type == Gst.MessageType.ERROR:
                print('element error:', m.parse_error())
            break
        s = m.get_structure()
        if s.get_name() != 'projtrack':
            continue
        has = s.has_field('area')
        row = (s.get_string('status'),
               (s.get_value('centroid-x'), s.get_value('centroid-y')) if has else None,
               s.get_value('area') if has else None)
        rows.append((s.get_value('id') if s.has_field('id') else 0, row) if by_id else row)
    pipeline.set_state(Gst.State.NULL)
    if by_id:
        return {id: [row for i, row in rows if i == id] for id in sorted({i for i, _ in rows})}
    return rows


def run_python_objects(frames):
    """{id: rows} of a MultiTracker with the cup from BOX and the hand from HAND."""
    t = projtrack.MultiTracker()
    ids = [t.add(frames[0][0], box=BOX), t.add(frames[0][0], point=HAND)]
    rows = {id: [] for id in ids}
    for f, _ in frames:
        for id, r in t.track(f, mask=False).items():
            rows[id].append((r.status, r.centroid, r.area))
    return rows


def compare(name, element, python):
    """The frames where the two differ, as lines; and how many frames were ok on each side."""
    bad = []
    if len(element) != len(python):
        bad.append(f'{name}: {len(element)} element messages, {len(python)} Python results')
    for i, (e, p) in enumerate(zip(element, python)):
        why = []
        if e[0] != p[0]:
            why.append(f'status {e[0]} vs {p[0]}')
        if e[1] is not None and p[1] is not None:
            if max(abs(e[1][0] - p[1][0]), abs(e[1][1] - p[1][1])) > 1.5:
                why.append(f'centroid {e[1]} vs {p[1]}')
            if abs(e[2] - p[2]) > 0.03 * max(e[2], p[2]):
                why.append(f'area {e[2]:.0f} vs {p[2]:.0f}')
        elif (e[1] is None) != (p[1] is None):
            why.append(f'features {e[1]} vs {p[1]}')
        if why:
            bad.append(f'{name} frame {i}: ' + ', '.join(why))
    return bad


def main():
    if not os.path.exists(CUP):
        print(f'no {CUP} (opencv-doc): skipped')
        return 77
    Gst.init(None)
    if Gst.ElementFactory.find('projtrack') is None:
        print('no projtrack element (GST_PLUGIN_PATH): skipped')
        return 77
    frames = cup_frames(FRAMES)
    failures = []
    for change in ('size', 'format', 'joined'):
        given = scenario(frames, change)
        element, python = run_element(given), run_python(given)
        failures += compare(change, element, python)
        first = FRAMES if change == 'joined' else CHANGE
        after = [r[0] for r in python[first:GRAY_HOLDS if change == 'format' else None]]
        ok = after.count('ok')
        print(f'{change}: {ok} of {len(after)} frames ok after the change; '
              f'{sum(e[0] == p[0] for e, p in zip(element, python))} statuses agree')
        if ok < 0.9 * len(after):
            failures.append(f'{change}: the track is not kept after the change ({after})')
    # Several objects: the cup from its box and the hand from a point, in the element's
    # start-boxes and start-points and in a MultiTracker, each object by its id.
    given = scenario(frames, 'none')
    element = run_element(given, 'start-boxes="<<{},{},{},{}>>" start-points="<<{},{}>>"'.format(
        *BOX, *HAND), by_id=True)
    python = run_python_objects(given)
    if sorted(element) != sorted(python):
        failures.append(f'objects: the element reported ids {sorted(element)}, '
                        f'Python {sorted(python)}')
    for id in python:
        failures += compare(f'object {id}', element.get(id, []), python[id])
        print(f'object {id}: measured on {sum(r[1] is not None for r in python[id])} of {len(given)} frames; '
              f'{sum(e[0] == p[0] for e, p in zip(element.get(id, []), python[id]))} statuses agree')
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
