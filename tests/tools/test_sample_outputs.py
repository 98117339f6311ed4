#!/usr/bin/python3
"""tools/sample_outputs.py's check: a sample that differs from its run by any number fails it,
but for what its command measures in time. Usage: test_sample_outputs.py SOURCE_DIR"""
import os
import sys

sys.path.insert(0, os.path.join(sys.argv[1], 'tools'))
import sample_outputs  # noqa: E402

failures = []


def check(condition, what):
    print(('ok   ' if condition else 'FAIL ') + what)
    if not condition:
        failures.append(what)


varies = {name: c[3] for name, c in sample_outputs.commands('/tmp').items()}
cursor = ('$ GST_PLUGIN_PATH=$PWD/build/gst examples/cursor3d.py --generated\n'
          '   0.13s  acquired an object\n'
          '   2.40s  push  at x -0.21 y -0.04 depth 1.13\n'
          '116 frames tracked, 1 push(es); wrote out/trajectory.csv and out/trajectory.png\n')
check(sample_outputs.difference(cursor, cursor, varies['cursor3d']) == '', 'the same: no diff')
for old, new in [('0.13s', '0.53s'), ('1.13', '1.14'), ('116 frames', '104 frames'),
                 ('-0.21', '0.21'), ('acquired', 'found')]:
    diff = sample_outputs.difference(cursor.replace(old, new), cursor, varies['cursor3d'])
    check(old in diff and new in diff, f'cursor3d: {new} for {old} is a difference')

demo = ('projtrack demo: gap-tolerant-filling, 640x480, 300 frames\n'
        '  tracked        300/300 frames\n'
        '  centroid error mean 4.16 px, max 11.96 px\n'
        '  time per frame median 1.89 ms (edges + estimate + overlay)\n')
check(sample_outputs.difference(demo.replace('1.89 ms', '12.5 ms'), demo, varies['demo']) == '',
      'demo: a timing is no difference')
check(sample_outputs.difference(demo.replace('4.16', '4.17'), demo, varies['demo']) != '',
      'demo: an error of 4.17 px for 4.16 is a difference')
check(sample_outputs.difference(demo.replace('300/300', '299/300'), demo, varies['demo']) != '',
      'demo: a frame fewer tracked is a difference')
check(all(v == [] for k, v in varies.items()
          if k in ('cursor3d', 'read-roi-meta', 'pointer-dry-run')),
      'the runs that measure no time are compared number by number')

print(f'{len(failures)} failures')
sys.exit(1 if failures else 0)
