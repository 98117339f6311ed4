#!/usr/bin/python3
"""The speed benchmark's quick mode end to end: it runs, measures every method and the frame copy
at both sizes, the library allocates nothing per frame (a count, not a time), memory stays flat,
and the report renders every target. Times are never asserted.

    test_speed_quick.py PROJTRACK_SPEED REPORT_PY OUT_DIR
"""
import csv
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

# The library's steady state allocates nothing, for every method: a count, exact.
for m in methods:
    v = find('allocations', f'Tracker::track {m}', 'per_frame')
    assert v == [0.0], (m, v)
# The element allocates only GStreamer's per-frame objects: fewer without messages.
on = find('allocations', 'projtrack element (messages on)', 'per_frame')[0]
off = find('allocations', 'projtrack element (post-messages=false)', 'per_frame')[0]
assert 0 <= off < on, (on, off)
rss0 = find('memory', 'projtrack element', 'rss_kib_at_1000')[0]
rss1 = find('memory', 'projtrack element', 'rss_kib_at_end')[0]
assert rss1 - rss0 < 1024, (rss0, rss1)
for size_row in [r for r in rows if r['section'] == 'size']:
    assert float(size_row['value']) > 0, size_row
assert find('streams', '8 streams', 'fps', clip='generated')[0] > 0

doc = os.path.join(out, 'performance.md')
subprocess.run([sys.executable, report, out, doc], check=True, timeout=300)
text = open(doc).read()
for target in ['| 1 |', '| 2 |', '| 3 |', '| 4 |', '| 5 |', '| 6 |']:
    assert target in text, target
assert 'nan' not in text.lower().replace('nanosec', ''), 'a NaN in the report'
assert os.path.exists(os.path.join(out, 'figures', 'cost_by_object_size.svg'))
print('speed quick run and report: ok')
