#!/usr/bin/python3
"""examples/track_numpy.py, projtrack beside OpenCV's tracker, as a user runs it: one line per
frame for each tracker, a summary, and the picture. Usage: test_track_numpy.py SOURCE OUTDIR
(PYTHONPATH=<build>/python)."""
import csv
import os
import re
import subprocess
import sys

import cv2

source, out_dir = sys.argv[1], sys.argv[2]
script = os.path.join(source, 'examples', 'track_numpy.py')
os.makedirs(out_dir, exist_ok=True)
FRAME = re.compile(r'^\s*(\d+)  (\S+)\s+(?:box (\d+),(\d+) (\d+)x(\d+)\s+area\s+(\d+) px²)?.*?'
                   r'  (ok\s+box (\d+),(\d+) (\d+)x(\d+)|lost|-)$')


def run(*args):
    done = subprocess.run([script, *args], capture_output=True, text=True, timeout=240)
    assert done.returncode == 0, (args, done.returncode, done.stderr)
    lines = done.stdout.splitlines()
    frames = [FRAME.match(line) for line in lines[1:] if not line.startswith(('projtrack', 'Open'))]
    assert all(frames), lines
    return lines, frames


# The generated hand, with KCF: both from the hand's first box, both on every frame.
lines, frames = run('--generated', '--frames', '20', '--opencv', 'kcf')
assert lines[0].split()[:2] == ['frame', 'projtrack'] and 'OpenCV KCF' in lines[0], lines[0]
assert [int(f[1]) for f in frames] == list(range(20))
assert all(f[2] == 'ok' for f in frames), lines
assert all(f[8].startswith('ok') for f in frames), lines
first = [int(v) for v in frames[0].group(3, 4, 5, 6)]
kcf_first = [int(v) for v in frames[0].group(9, 10, 11, 12)]
assert all(abs(a - b) <= 8 for a, b in zip(first, kcf_first)), (first, kcf_first)
assert re.match(r'projtrack \(gap-tolerant-filling\): the object on 20 of 20 frames', lines[-2])
assert lines[-1].startswith('OpenCV KCF: the object on '), lines[-1]

# From a point: OpenCV's tracker starts from projtrack's first box.
lines, frames = run('--generated', '--frames', '3', '--point', '224,264', '--opencv', 'mil')
assert frames[0][2] == 'ok' and frames[0].group(3, 4, 5, 6) == frames[0].group(9, 10, 11, 12)

# opencv-doc's cup from its first true box: projtrack's box stays near the truth's, and the
# picture is written.
cup = '/usr/share/doc/opencv-doc/opencv4/html/cup.mp4.gz'
if os.path.exists(cup):
    picture = os.path.join(out_dir, 'cup.png')
    lines, frames = run('--frames', '30', '--picture', picture, '--picture-frame', '20')
    with open(os.path.join(source, 'bench', 'real', 'truth', 'cup.csv'), newline='') as f:
        truth = list(csv.DictReader(f))
    # Its left, top and bottom edges near the truth's and its area within the real-footage bench's
    # bounds (0.5-2x): not its width, which on some frames takes the fingers on the cup's right
    # (up to 184 px against 107 on the first): frames are read at video range, as the element
    # reads the decoder's I420, which took them there before (216 px; docs/element.md#formats).
    for f in frames:
        t = truth[int(f[1])]
        assert f[2] == 'ok', f[0]
        x, y, w, h = (int(v) for v in f.group(3, 4, 5, 6))
        edges = (x, y, y + h)
        want = (int(t['x']), int(t['y']), int(t['y']) + int(t['height']))
        assert all(abs(a - b) <= 12 for a, b in zip(edges, want)), (f[0], t)
        assert 0.5 <= int(f.group(7)) / float(t['area']) <= 2, (f[0], t)
    image = cv2.imread(picture)
    assert image is not None and image.shape == (480, 640, 3), picture
else:
    print(f'no {cup}: the cup run is left out')
print('track_numpy: ok')
