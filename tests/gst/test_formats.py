#!/usr/bin/python3
"""The same answer in every pixel format (issue 32 item 3): one picture of opencv-doc's cup in
every format, started from a box and from a point, gives the same status, area and box on every
one of its first frames, within a few per cent of I420's. Limited-range YUV is read as it is,
RGB converted by the library to that range, full-range gray mapped to it, and chroma stored per
2x2, 2x1 or 1x1 pixels averaged over each work block: every format of one picture gives the
tracker the same colours. GRAY8 only tracks from the box: without colour the dark cup and the
shadowed fingers on it are one region, and from the point no region stands apart (as before
this test). Exit status 0 when they agree, 77 (skipped) without the clip.

One picture: the decoder's I420 frames, rewritten into each layout by copying their samples and
into RGB by OpenCV's cvtColor (whose RGB the library turns back into the same I420 within
rounding), pushed through appsrc. Not videoconvert's conversions: GStreamer 1.22's videoconvert
turns limited-range YUV into RGB 1-4 levels too dark (luma 235 gives white 253; on the cup's
first frame B -1.5, G -4.0, R -2.9 on average against OpenCV's) and RGB into YUV about half a
level low (luma -0.34, Cb -0.59 on average against BT.601 rounded), so its formats of one frame
are other pictures, and the cup's first frame is a close call (docs/element.md, "Formats"). The
README's pipeline, `decodebin ! videoconvert` into RGB, is compared with the decoder's I420 from
the box: the box start cuts the cup out of the user's box, where the call is no longer close.
Areas agree within AREA_TOLERANCE, boxes within TOLERANCE."""
import gzip
import os
import shutil
import sys
import tempfile

import cv2
import gi
import numpy as np
gi.require_version('Gst', '1.0')
from gi.repository import Gst  # noqa: E402

CLIP = '/usr/share/doc/opencv-doc/opencv4/html/cup.mp4.gz'
# I420-full: I420 at full range (colorimetry 1:4:0:0, as jpegdec gives), mapped down by the element.
FORMATS = ['YV12', 'NV12', 'NV21', 'YUY2', 'UYVY', 'Y444', 'I420-full', 'BGR', 'BGRx', 'RGBA']
STARTS = {'box': 'start-box="<308,126,104,256>"', 'point': 'inner-point-x=360 inner-point-y=254'}
FRAMES = 20
CONVERTED = ['BGR', 'BGRx', 'RGBA']  # videoconvert's formats compared with the decoder's I420
TOLERANCE = 0.05  # of the reference's box sides
# Of its area: the flow model leaves holes where the evidence wavers (filling them cost davis-dev
# 3-4 J), and a level's rounding between formats opens or closes a few of them inside the same
# outline (the cup: areas up to 6.9 % apart with boxes within 0.8 %).
AREA_TOLERANCE = 0.08
TRACKING = ('ok', 'reached-border')


def decoded_i420(clip):
    """The first FRAMES frames as the decoder gives them: (Y, U, V) planes and the size."""
    p = Gst.parse_launch(f'filesrc location={clip} ! decodebin ! videoconvert ! '
                         'video/x-raw,format=I420 ! appsink name=out sync=false')
    sink = p.get_by_name('out')
    p.set_state(Gst.State.PLAYING)
    frames = []
    for _ in range(FRAMES):
        sample = sink.emit('pull-sample')
        s = sample.get_caps().get_structure(0)
        w, h = s.get_value('width'), s.get_value('height')
        ok, m = sample.get_buffer().map(Gst.MapFlags.READ)
        data = np.frombuffer(m.data, np.uint8).copy()
        sample.get_buffer().unmap(m)
        n, q = w * h, (w // 2) * (h // 2)
        frames.append((data[:n].reshape(h, w), data[n:n + q].reshape(h // 2, w // 2),
                       data[n + q:n + 2 * q].reshape(h // 2, w // 2)))
    p.set_state(Gst.State.NULL)
    return frames, w, h


def as_format(y, u, v, fmt):
    """The I420 planes (y, u, v) as one `fmt` frame's bytes: samples copied, RGB converted."""
    if fmt == 'I420':
        return np.concatenate([y.ravel(), u.ravel(), v.ravel()])
    if fmt == 'I420-full':
        return np.concatenate([full_range(y, 16, 255 / 219).ravel(),
                               full_range(u, 128, 255 / 224).ravel(),
                               full_range(v, 128, 255 / 224).ravel()])
    if fmt == 'YV12':
        return np.concatenate([y.ravel(), v.ravel(), u.ravel()])
    if fmt in ('NV12', 'NV21'):
        pair = np.stack([u, v] if fmt == 'NV12' else [v, u], axis=-1)
        return np.concatenate([y.ravel(), pair.ravel()])
    rows_u, rows_v = np.repeat(u, 2, axis=0), np.repeat(v, 2, axis=0)  # 4:2:0 rows twice
    if fmt in ('YUY2', 'UYVY'):
        packed = np.empty((y.shape[0], y.shape[1] * 2), np.uint8)
        luma, chroma = (0, 1) if fmt == 'YUY2' else (1, 0)
        packed[:, luma::2] = y
        packed[:, chroma::4], packed[:, chroma + 2::4] = rows_u, rows_v
        return packed.ravel()
    if fmt == 'Y444':
        return np.concatenate([y.ravel(), np.repeat(rows_u, 2, axis=1).ravel(),
                               np.repeat(rows_v, 2, axis=1).ravel()])
    i420 = np.concatenate([y, u.reshape(-1, y.shape[1]), v.reshape(-1, y.shape[1])])
    bgr = cv2.cvtColor(i420, cv2.COLOR_YUV2BGR_I420)
    if fmt == 'BGR':
        return bgr.ravel()
    if fmt == 'BGRx':
        return cv2.cvtColor(bgr, cv2.COLOR_BGR2BGRA).ravel()
    if fmt == 'RGBA':
        return cv2.cvtColor(bgr, cv2.COLOR_BGR2RGBA).ravel()
    assert fmt == 'GRAY8'  # full range, as GStreamer's GRAY8 and OpenCV's gray
    return full_range(y, 16, 255 / 219).ravel()


def full_range(plane, zero, gain):
    """A video-range plane at full range: `zero` (black, or neutral chroma) to 0 (128)."""
    base = 0 if zero == 16 else 128
    return np.clip(np.rint(base + (plane.astype(float) - zero) * gain), 0, 255).astype(np.uint8)


def track_converted(clip, fmt, start):
    """Status, area and box of every frame of the README's pipeline: the decoder's frames through
    videoconvert into `fmt`."""
    p = Gst.parse_launch(f'filesrc location={clip} ! decodebin ! videoconvert ! '
                         f'video/x-raw,format={fmt} ! projtrack {start} ! '
                         f'fakesink sync=false num-buffers={FRAMES}')
    return messages(p, FRAMES)


def track(frames, w, h, fmt, start):
    """Status, area and box of every frame given in `fmt`."""
    colorimetry = ',colorimetry=bt601' if fmt not in ('BGR', 'BGRx', 'RGBA', 'GRAY8') else ''
    if fmt == 'I420-full':
        colorimetry = ',colorimetry=1:4:0:0'  # range 0-255, BT.601: JPEG's
    caps = f'video/x-raw,format={fmt.split("-")[0]},width={w},height={h},framerate=25/1' \
        + colorimetry
    p = Gst.parse_launch(f'appsrc name=src format=time caps="{caps}" ! '
                         f'projtrack {start} ! fakesink sync=false')
    src = p.get_by_name('src')
    p.set_state(Gst.State.PLAYING)
    for i, (y, u, v) in enumerate(frames):
        buf = Gst.Buffer.new_wrapped(as_format(y, u, v, fmt).tobytes())
        buf.pts, buf.duration = i * Gst.SECOND // 25, Gst.SECOND // 25
        src.emit('push-buffer', buf)
    src.emit('end-of-stream')
    return messages(p, len(frames))


def messages(p, n):
    """Status, area and box of the first `n` frames from the playing pipeline `p`'s messages."""
    bus = p.get_bus()
    p.set_state(Gst.State.PLAYING)
    rows = []
    while len(rows) < n:
        m = bus.timed_pop_filtered(30 * Gst.SECOND, Gst.MessageType.ELEMENT |
                                   Gst.MessageType.EOS | Gst.MessageType.ERROR)
        if m is None or m.type != Gst.MessageType.ELEMENT:
            break
        s = m.get_structure()
        if s.get_name() != 'projtrack':
            continue
        status = s.get_string('status')
        box = tuple(s.get_value(k) for k in ('x', 'y', 'width', 'height')) \
            if status in TRACKING else None
        rows.append((status, s.get_value('area') if box else 0.0, box))
    p.set_state(Gst.State.NULL)
    return rows


def near(a, b, scale, tolerance=TOLERANCE):
    return abs(a - b) <= tolerance * scale


def compare(name, rows, ref, failures):
    if len(rows) != len(ref):
        failures.append(f'{name}: {len(rows)} frames, the reference {len(ref)}')
        return
    for i, ((st, area, box), (rst, rarea, rbox)) in enumerate(zip(rows, ref)):
        if st != rst:
            failures.append(f'{name} frame {i}: status {st}, I420 {rst}')
        elif box and not (near(area, rarea, rarea, AREA_TOLERANCE) and
                          all(near(box[k], rbox[k], max(rbox[2], rbox[3])) for k in range(4))):
            failures.append(f'{name} frame {i}: area {area:.0f} box {box}, '
                            f'I420 {rarea:.0f} {rbox}')


def tracks_every_frame(rows):
    return len(rows) == FRAMES and all(st in TRACKING for st, _, _ in rows)


def main():
    if not os.path.exists(CLIP):
        print(f'{CLIP} is missing (Debian package opencv-doc): skipped')
        return 77
    Gst.init(None)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        clip = os.path.join(tmp, 'cup.mp4')
        with gzip.open(CLIP) as src, open(clip, 'wb') as dst:
            shutil.copyfileobj(src, dst)
        frames, w, h = decoded_i420(clip)
        # The README's pipeline, videoconvert's RGB another picture within a few levels: a box
        # start gives the same silhouette from it as from the decoder's I420.
        ref = track_converted(clip, 'I420', STARTS['box'])
        for fmt in CONVERTED:
            rows = track_converted(clip, fmt, STARTS['box'])
            compare(f'box through videoconvert {fmt}', rows, ref, failures)
            print(f'box through videoconvert {fmt}: frame 0 area {rows[0][1]:.0f} box '
                  f'{rows[0][2]}, I420 {ref[0][1]:.0f} {ref[0][2]}')
    for start_name, start in STARTS.items():
        ref = track(frames, w, h, 'I420', start)
        if not tracks_every_frame(ref):
            failures.append(f'{start_name}: I420 does not track every frame: {ref}')
        print(f'{start_name} I420: frame 0 area {ref[0][1]:.0f} box {ref[0][2]}, '
              f'frame {FRAMES - 1} {ref[-1][1]:.0f} {ref[-1][2]}')
        for fmt in FORMATS:
            rows = track(frames, w, h, fmt, start)
            compare(f'{start_name} {fmt}', rows, ref, failures)
            print(f'{start_name} {fmt}: frame 0 area {rows[0][1]:.0f} box {rows[0][2]}')
    if not tracks_every_frame(track(frames, w, h, 'GRAY8', STARTS['box'])):
        failures.append('box GRAY8: does not track every frame')
    for f in failures[:40]:
        print(f)
    print(f'{len(failures)} disagreements')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
