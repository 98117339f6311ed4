#!/usr/bin/python3
"""docs/element.md's two-object pipeline, run as written: the gst-launch-1.0 command under the
comment "# two objects at once" (its continuation lines joined). Every frame must post one
projtrack message per object, with id 1 and id 2, each following its own ball.

Usage: test_doc_objects.py docs/element.md (the plugin on GST_PLUGIN_PATH)."""
import re
import shlex
import subprocess
import sys


def documented_command(doc_path):
    lines = open(doc_path, encoding='utf-8').read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith('# two objects at once'))
    command = ''
    for line in lines[start + 1:]:
        command += line.rstrip('\\').strip() + ' '
        if not line.endswith('\\'):
            break
    return command


def main():
    command = documented_command(sys.argv[1])
    assert command.startswith('gst-launch-1.0 '), command
    run = subprocess.run(shlex.split(command), capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    messages = [line for line in run.stdout.splitlines() if 'projtrack, status=' in line]
    centroids = {1: [], 2: []}
    for m in messages:
        found = re.search(r'\bid=\(int\)(\d+)', m)
        assert found, 'a message without an id: ' + m
        x = float(re.search(r'centroid-x=\(double\)([0-9.e+-]+)', m).group(1))
        centroids[int(found.group(1))].append(x)
    assert len(centroids[1]) == 30 and len(centroids[2]) == 30, {k: len(v) for k, v in centroids.items()}
    # The left ball stays in the left half, the right one in the right half.
    assert all(x < 160 for x in centroids[1]) and all(x >= 160 for x in centroids[2]), centroids
    print('doc_objects: ok,', len(messages), 'messages')


main()
