#!/usr/bin/python3
"""The benchmark's quick mode end to end: the tool runs, every method of the library's table and
every peer appears, the scenes' ground truth agrees with the independent counts, and the report
renders every claim.

    test_bench_quick.py PROJTRACK_BENCH REPORT_PY OUT_DIR
"""
import csv
import math
import os
import shutil
import subprocess
import sys

bench, report, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
subprocess.run([bench, '--quick', '--out', out], check=True, timeout=600)

# The library's table of methods, as the tool lists it and as it wrote it beside its results.
listed = subprocess.run([bench, '--list-methods'], check=True, capture_output=True, text=True,
                        timeout=60).stdout
table = list(csv.DictReader(listed.splitlines()))
assert open(os.path.join(out, 'methods.csv')).read() == listed
assert len(table) >= 7 and len({m['method'] for m in table}) == len(table), table
for m in table:
    assert m['family'] in ('rays', 'fill') and m['iterative'] in ('0', '1'), m
    assert m['trace'] in ('rays', 'rays-and-blocks', 'filled-pixels', 'grid-lines'), m

runs = list(csv.DictReader(open(os.path.join(out, 'runs.csv'))))
methods = {r['method'] for r in runs}
expected = {m['method'] for m in table} | {'opencv-floodfill', 'opencv-components'}
assert methods == expected, methods
for r in runs:
    assert r['status'], r
    if r['area']:
        assert math.isfinite(float(r['area'])) and float(r['time_us']) >= 0, r

scenes = list(csv.DictReader(open(os.path.join(out, 'scenes.csv'))))
assert scenes
for s in scenes:
    assert s['truth_consistent'] == '1', s
    assert abs(float(s['true_area']) / float(s['supersampled_area']) - 1) < 0.01, s
    if float(s['analytic_area']) > 0:
        assert abs(float(s['true_area']) / float(s['analytic_area']) - 1) < 0.005, s

variants = list(csv.DictReader(open(os.path.join(out, 'variants.csv'))))
assert {(r['parameter'], r['method']) for r in variants} == {
    ('grid_size', 'grid-filling'), ('max_gap', 'gap-tolerant-filling')}, variants[:2]

doc = os.path.join(out, 'benchmarks.md')
subprocess.run([sys.executable, report, out, doc], check=True, timeout=300)
text = open(doc).read()
for claim in ['C1', 'C2', 'C3', 'C4', 'C5', 'C6']:
    assert f'| {claim}: ' in text, claim
for m in expected:
    assert f'| {m} |' in text, m
assert 'nan' not in text.lower(), 'a NaN in the report'
assert 'not recorded' not in text, 'a setting the benchmark did not record'
figures = ['gap-rate.png', 'time-resolution.png', 'sweep.png']
figures += [f'{m["method"]}-{obj}.png' for m in table for obj in ('sphere', 'hand')]
for f in figures:
    assert os.path.getsize(os.path.join(out, 'figures', f)) > 1000, f
print('bench quick: ok')
