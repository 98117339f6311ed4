#!/usr/bin/python3
"""The speed benchmark's quick mode end to end: it runs, measures every method and the frame copy
at both sizes, the library allocates nothing per frame (a count, not a time), memory stays flat,
and the report renders every target. Times are never asserted.

    test_speed_quick.py PROJTRACK_SPEED REPORT_PY OUT_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys

speed, report, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
subprocess.run([speed, '--quick', '--out', out], check=True, timeout=600)

rows = list(csv.DictReader(open(os.path.join(out, 'speed.csv'))))
# Every method of the library's table, as the tool wrote it beside its measurements.
methods = [m['method'] for m in csv.DictReader(open(os.path.join(out, 'methods.csv')))]
assert len(methods) >= 7, methods


def find(section, what, key, res=None, clip='generated'):
    return [float(r['value']) for r in rows if r['section'] == section and r['what'] == what
            and r['key'] == key and r['clip'] == clip and (res is None or r['resolution'] == res)]


for res in ['640x480', '1920x1080']:
    for what in ['frame copy', 'cv::Canny + cv::floodFill'] + [f'projtrack {m}' for m in methods]:
        v = find('per_frame', what, 'median_us', res)
        assert len(v) == 1 and v[0] > 0, (res, what, v)
        if what.startswith('projtrack'):
            assert find('ratio', f'{what} / frame copy', 'median', res)[0] > 0

# The library's steady state with the edges model allocates nothing, for every method: a count,
# exact. The default model's count is measured and reported (its target, none, is not met yet:
# OpenCV's DIS, warpAffine, GaussianBlur and erode allocate within each call), never lost.
for m in methods:
    v = find('allocations', f'Tracker::track {m} (edges model)', 'per_frame')
    assert v == [0.0], (m, v)
    v = find('allocations', f'Tracker::track {m}', 'per_frame')
    assert len(v) == 1 and 0 <= v[0] < float('inf'), (m, v)
# The element allocates only GStreamer's per-frame objects: fewer without messages.
on = find('allocations', 'projtrack element (messages on)', 'per_frame')[0]
off = find('allocations', 'projtrack element (post-messages=false)', 'per_frame')[0]
assert 0 <= off < on, (on, off)
rss0 = find('memory', 'projtrack element', 'rss_kib_at_mark')[0]
rss1 = find('memory', 'projtrack element', 'rss_kib_at_end')[0]
assert rss1 - rss0 < 1024, (rss0, rss1)
for size_row in [r for r in rows if r['section'] == 'size']:
    assert float(size_row['value']) > 0, size_row
# Every frame pushed to the concurrent streams came back tracked, in time, without error.
for what in ['1 stream', '8 streams']:
    pushed = find('streams', what, 'frames_pushed')[0]
    assert pushed > 0 and find('streams', what, 'frames_tracked') == [pushed], what
    assert find('streams', what, 'pushes_refused') == [0.0], what
    assert find('streams', what, 'timeouts') == [0.0] and find('streams', what, 'errors') == [0.0]
    assert find('streams', what, 'fps')[0] > 0
# Our blur and Canny beside OpenCV's on every region measured.
regions = [r['what'] for r in rows if r['section'] == 'edge_region']
assert regions, 'no edge regions'
for region in regions:
    for what in ['projtrack box blur', 'cv::blur', 'projtrack Canny', 'cv::Canny']:
        res = [r for r in rows if r['section'] == 'edge_stages' and r['what'] == what
               and r['key'] == region]
        assert len(res) == 1 and float(res[0]['value']) > 0, (region, what)
assert json.load(open(os.path.join(out, 'meta.json')))['measured'].endswith('UTC')
# Bounded work at 1080p: every method's ordinary median and worst adversarial frames, the extreme
# settings, and set_state(NULL) during a heavy frame, whose every frame ended interrupted.
hd = '1920x1080'
for m in methods:
    assert find('adversarial', m, 'median_us', hd)[0] > 0, m
    worst = [float(r['value']) for r in rows if r['section'] == 'adversarial'
             and r['what'].startswith(m + ' ') and r['key'] == 'worst_us']
    assert worst and min(worst) > 0, (m, worst)
# The work ordinary frames need, for both models and every method, at 640×480: on the generated
# clip, and on the real one when opencv-doc is installed.
real = any(r['section'] == 'ordinary_work' and r['clip'] == 'real' for r in rows)
for clip in ['generated'] + (['real'] if real else []):
    for model in ['flow', 'edges']:
        for m in methods:
            assert find('ordinary_work', f'{model} {m}', 'max_x', '640x480', clip)[0] > 0, (clip, m)
            assert find('ordinary_work', f'{model} {m}', 'frames', '640x480', clip)[0] > 0
extreme = [r for r in rows if r['section'] == 'extreme' and r['key'] == 'worst_us']
assert extreme and all(float(r['value']) > 0 for r in extreme), extreme
trials = find('interrupt', 'set_state(NULL) during a heavy frame', 'trials', hd, 'uniform')
assert trials and trials[0] > 0, trials
assert find('interrupt', 'set_state(NULL) during a heavy frame', 'frames_interrupted', hd,
            'uniform') == trials

doc = os.path.join(out, 'performance.md')
subprocess.run([sys.executable, report, out, doc], check=True, timeout=300)
text = open(doc).read()
for target in ['| 1 |', '| 2 |', '| 3 |', '| 4 |', '| 5 |', '| 6 |', '| 7 |', '| 8 |', '| 9 |']:
    assert target in text, target
assert 'nan' not in text.lower().replace('nanosec', ''), 'a NaN in the report'
# cvtracker (target 3) needs gstreamer1.0-opencv, which only ./run bench --speed installs.
assert 'not recorded' not in text, 'a setting the benchmark did not record'
for target in ['| 1 |', '| 2 |', '| 4 |', '| 5 |', '| 6 |', '| 7 |', '| 8 |', '| 9 |']:
    line = next(ln for ln in text.splitlines() if ln.startswith(target))
    assert 'not measured' not in line, line
assert os.path.exists(os.path.join(out, 'figures', 'cost_by_object_size.svg'))
print('speed quick run and report: ok')
