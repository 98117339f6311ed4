#!/usr/bin/python3
"""Runs the examples and the demo as a user would, and checks what they print and write.

    test_examples.py c BINARY | python SCRIPT | demo SCRIPT OUTDIR | cursor SCRIPT OUTDIR
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


def check_cursor(script, out_dir):
    png = os.path.join(out_dir, 'trajectory.png')
    out = subprocess.run([script, '--generated', '--frames', '100', '--out', png],
                         capture_output=True, text=True, timeout=300, check=True).stdout
    assert 'acquired an object' in out, out
    assert sum(' push ' in line for line in out.splitlines()) == 1, out
    assert os.path.getsize(png) > 10000


kind = sys.argv[1]
if kind in ('c', 'python'):
    check_feature_lines([sys.argv[2]])
elif kind == 'demo':
    check_demo(sys.argv[2], sys.argv[3])
elif kind == 'cursor':
    check_cursor(sys.argv[2], sys.argv[3])
else:
    sys.exit(f'unknown kind {kind}')
print(f'{kind}: ok')
