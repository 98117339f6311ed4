#!/usr/bin/python3
"""Regenerates the sample outputs that README.md and docs/ show, from runs: never typed.

A sample in a Markdown file is a fenced block between two markers:

    <!-- sample: NAME -->
    ```
    ...what the command NAME printed...
    ```
    <!-- end of sample -->

and the overlay's pictures in docs/element/ are frames the element drew on opencv-doc's cup clip
at 640x480 (when opencv-doc and the H.264 decoder are installed: ./run docs installs them), the
Python example's picture in docs/python/ one it drew on the same clip.

    tools/sample_outputs.py [--build build]          # rewrite the samples and pictures
    tools/sample_outputs.py --check [--build build]  # run the commands; fail where a sample
                                                     # differs from what runs now

The runs are deterministic (generated frames, the element's work counted in units, never in
time), so the check compares every number, but for what each command measures in time (its
`varies` patterns: timings), whose digits it masks.

Run with the plugin on GST_PLUGIN_PATH (./run docs sets it); the Python module is taken from
the build folder (PYTHONPATH=BUILD/python).
"""
import argparse
import difflib
import gzip
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PY = '/usr/bin/python3'
DOCS = ['README.md', 'docs/development.md', 'docs/element.md', 'docs/python.md']
SAMPLE = re.compile(r'(<!-- sample: ([a-z0-9-]+) -->\n```[a-z]*\n)(.*?)(```\n<!-- end of sample -->)',
                    re.S)


# What varies from run to run in a sample: times measured on the clock.
TIMING = r'[\d.]+ ms'


def commands(out):
    """NAME: (what the sample shows as typed, the command run in `out`, how many lines to keep,
    patterns of what varies run to run)."""
    ex = os.path.join(ROOT, 'examples')
    return {
        'demo': (None, [PY, f'{ex}/demo.py'], None, [TIMING]),
        'cursor3d': ('$ GST_PLUGIN_PATH=$PWD/build/gst examples/cursor3d.py --generated',
                     [PY, f'{ex}/cursor3d.py', '--generated'], None, []),
        'print-features': ('$ GST_PLUGIN_PATH=$PWD/build/gst examples/print_features.py | head -4',
                           [PY, f'{ex}/print_features.py'], 4, [TIMING]),
        'read-roi-meta': ('$ GST_PLUGIN_PATH=$PWD/build/gst examples/read_roi_meta.py | head -3',
                          [PY, f'{ex}/read_roi_meta.py'], 3, []),
        'pointer-dry-run': ('$ GST_PLUGIN_PATH=$PWD/build/gst examples/pointer_uinput.py '
                            '--dry-run --generated | head -7',
                            [PY, f'{ex}/pointer_uinput.py', '--dry-run', '--generated'], 7, []),
        'track-numpy': ('$ PYTHONPATH=build/python examples/track_numpy.py --frames 3',
                        [PY, f'{ex}/track_numpy.py', '--frames', '3'], None, [TIMING]),
        'track-several': ('$ PYTHONPATH=build/python examples/track_several.py --quiet',
                          [PY, f'{ex}/track_several.py', '--quiet'], None, []),
    }


def run(name, out, build):
    """The command's output, run in `out` as a user runs it in the source tree (relative paths
    such as out/demo.webm land in `out`)."""
    shown, cmd, keep, _ = commands(out)[name]
    env = dict(os.environ, PYTHONPATH=os.path.join(build, 'python'))
    done = subprocess.run(cmd, cwd=out, capture_output=True, text=True, timeout=600, env=env)
    if done.returncode != 0:
        sys.exit(f'sample_outputs: {name} failed (exit code {done.returncode}):\n{done.stderr}')
    lines = [line for line in re.split(r'\r?\n', done.stdout) if line.strip()]
    lines = lines[:keep] if keep else lines
    return '\n'.join(([shown] if shown else []) + lines) + '\n'


def masked(text, varies):
    """`text` with the numbers in what matches a pattern of `varies` masked."""
    for pattern in varies:
        text = re.sub(pattern, lambda m: re.sub(r'\d+(\.\d+)?', '#', m.group(0)), text)
    return text


def difference(shown, now, varies):
    """How sample `shown` differs from output `now` (a diff), or '' when only what varies does."""
    a, b = masked(shown, varies), masked(now, varies)
    if a == b:
        return ''
    return ''.join(difflib.unified_diff(a.splitlines(True), b.splitlines(True), 'shown', 'now',
                                        n=1))


def overlay_pictures(out, build):
    """Frames of the cup clip with the overlay, at 640x480: tracking, and still searching."""
    clip = '/usr/share/doc/opencv-doc/opencv4/html/cup.mp4.gz'
    if not os.path.exists(clip) or shutil.which('gst-launch-1.0') is None:
        print(f'sample_outputs: no {clip}: the overlay pictures are left as they are')
        return
    frames = os.path.join(out, 'overlay')
    shutil.rmtree(frames, ignore_errors=True)
    os.makedirs(frames)
    with gzip.open(clip) as f, open(os.path.join(out, 'cup.mp4'), 'wb') as g:
        g.write(f.read())
    subprocess.run(['gst-launch-1.0', '-q', 'filesrc', f'location={out}/cup.mp4', '!', 'decodebin',
                    '!', 'videoconvert', '!', 'videoscale', '!',
                    'video/x-raw,format=I420,width=640,height=480', '!', 'projtrack', 'draw=true',
                    '!', 'videoconvert', '!', 'pngenc', '!', 'multifilesink',
                    f'location={frames}/%03d.png'], check=True, timeout=600)
    dest = os.path.join(ROOT, 'docs', 'element')
    os.makedirs(dest, exist_ok=True)
    for frame, name in [(5, 'overlay-searching.png'), (150, 'overlay-tracking.png')]:
        shutil.copy(os.path.join(frames, f'{frame:03d}.png'), os.path.join(dest, name))
        print(f'sample_outputs: wrote docs/element/{name}')


def python_picture(build):
    """The Python example's frame 80 of the cup: projtrack's silhouette and box, KCF's box."""
    picture = os.path.join(ROOT, 'docs', 'python', 'track-numpy.png')
    os.makedirs(os.path.dirname(picture), exist_ok=True)
    subprocess.run([PY, os.path.join(ROOT, 'examples', 'track_numpy.py'), '--frames', '81',
                    '--picture', picture, '--picture-frame', '80'], check=True, timeout=600,
                   stdout=subprocess.DEVNULL, env=dict(os.environ,
                                                       PYTHONPATH=os.path.join(build, 'python')))
    print('sample_outputs: wrote docs/python/track-numpy.png')


def several_picture(build):
    """The several-objects example's frames 0, 60 and 120 of the cup: the cup and the hand."""
    picture = os.path.join(ROOT, 'docs', 'python', 'cup-and-hand.png')
    subprocess.run([PY, os.path.join(ROOT, 'examples', 'track_several.py'), '--quiet',
                    '--frames', '121', '--picture', picture], check=True, timeout=600,
                   stdout=subprocess.DEVNULL, env=dict(os.environ,
                                                       PYTHONPATH=os.path.join(build, 'python')))
    print('sample_outputs: wrote docs/python/cup-and-hand.png')


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument('--build', default='build')
    ap.add_argument('--check', action='store_true')
    args = ap.parse_args()
    build = os.path.join(ROOT, args.build)
    out = os.path.join(build, 'samples')
    os.makedirs(out, exist_ok=True)
    outputs, problems = {}, []
    for doc in DOCS:
        path = os.path.join(ROOT, doc)
        text = open(path).read()

        def replace(m):
            name = m.group(2)
            if name not in outputs:
                outputs[name] = run(name, out, build)
            diff = difference(m.group(3), outputs[name], commands(out)[name][3])
            if args.check and diff:
                problems.append(f'{doc}: sample {name} differs from what runs now:\n{diff}')
            # A sample that differs only in what varies (timings) is kept as it is.
            return m.group(1) + outputs[name] + m.group(4) if diff else m.group(0)
        new = SAMPLE.sub(replace, text)
        if not args.check and new != text:
            open(path, 'w').write(new)
            print(f'sample_outputs: updated {doc}')
    unknown = set(commands(out)) - set(outputs)
    if unknown:
        problems.append(f'samples no document shows: {sorted(unknown)}')
    if args.check:
        for p in problems:
            print(p)
        print(f'{len(outputs)} samples checked, {len(problems)} out of date'
              + (' (./run docs regenerates them)' if problems else ''))
        return 1 if problems else 0
    overlay_pictures(out, args.build)
    python_picture(build)
    several_picture(build)
    return 0


if __name__ == '__main__':
    sys.exit(main())
