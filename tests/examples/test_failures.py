#!/usr/bin/python3
"""Every example fails cleanly: a message and an exit code, never a traceback, a GStreamer
CRITICAL or a crash; one CLI style (--help on each); output whose reader goes early (| head)
ends the run quietly.

    test_failures.py SOURCE_DIR PRINT_FEATURES_BINARY   (the plugin on GST_PLUGIN_PATH, the Python
                                                          module on PYTHONPATH)
"""
import fcntl
import os
import subprocess
import sys
import tempfile

source, c_binary = sys.argv[1], sys.argv[2]
EX = os.path.join(source, 'examples')
PY = '/usr/bin/python3'
failures = []


def script(name):
    return [PY, os.path.join(EX, name)]


def check(condition, what, detail=''):
    """Records `what`; `detail` is shown only when it fails."""
    print(('ok   ' if condition else 'FAIL ') + what + ('' if condition else detail), flush=True)
    if not condition:
        failures.append(what)


def clean(done, what):
    """No traceback, no GLib CRITICAL, not killed by a signal."""
    check(done.returncode >= 0, f'{what}: not killed by a signal', f' ({-done.returncode})')
    check('Traceback' not in done.stderr, f'{what}: no traceback', ':\n' + done.stderr)
    check('CRITICAL' not in done.stderr, f'{what}: no GStreamer CRITICAL', ':\n' + done.stderr)


def fails(cmd, code, words, what, env=None):
    """`cmd` exits with `code` and says `words` on stderr, cleanly."""
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=env,
                          stdin=subprocess.DEVNULL)
    clean(done, what)
    check(done.returncode == code, f'{what}: exit code {code}', f', not {done.returncode}')
    check(words in done.stderr, f'{what}: says {words!r}', f': {done.stderr!r}')


def first_line_then_close(cmd):
    """Runs `cmd` with its stdout in a one-page pipe, reads one line and closes the pipe, as
    `cmd | head -1` does once its line is read: (exit code, the line, stderr)."""
    r, w = os.pipe()
    fcntl.fcntl(w, 1031, 4096)  # F_SETPIPE_SZ: the writer blocks after a page, then finds it closed
    p = subprocess.Popen(cmd, stdout=w, stderr=subprocess.PIPE, text=True,
                         stdin=subprocess.DEVNULL)
    os.close(w)
    with os.fdopen(r) as reader:
        line = reader.readline()
    stderr = p.stderr.read()
    p.wait(timeout=120)
    return subprocess.CompletedProcess(cmd, p.returncode, line, stderr)


# One CLI style: --help on every example, usage on stdout, exit code 0.
for cmd in [[c_binary]] + [script(n) for n in ['print_features.py', 'read_roi_meta.py',
                                               'cursor3d.py', 'pointer_uinput.py', 'demo.py',
                                               'track_numpy.py', 'track_several.py']]:
    name = os.path.basename(cmd[-1])
    done = subprocess.run(cmd + ['--help'], capture_output=True, text=True, timeout=60)
    clean(done, f'{name} --help')
    check(done.returncode == 0 and done.stdout.startswith('usage: '),
          f'{name} --help: usage, exit code 0', f' ({done.returncode}): {done.stdout[:80]!r}')
    fails(cmd + ['--no-such-option'], 2, 'usage: ', f'{name} --no-such-option')

# Pipelines that cannot be built or run.
for cmd in ([c_binary], script('print_features.py')):
    name = os.path.basename(cmd[-1])
    fails(cmd + ['videotestsrc ! nonsense'], 2, 'no element "nonsense"', f'{name} nonsense')
    fails(cmd + ['videotestsrc num-buffers=3 ! fakesink'], 2, 'no projtrack element',
          f'{name} without projtrack')
    fails(cmd + ['videotestsrc'], 2, 'no projtrack element', f'{name} one element')
    fails(cmd + ['videotestsrc ! projtrack no-such-property=1 ! fakesink'], 2,
          'no property "no-such-property"', f'{name} a wrong property')
    fails(cmd + ['filesrc location=/nonexistent ! decodebin ! projtrack ! fakesink'], 1,
          'Resource not found', f'{name} a missing file')
    fails(cmd + ['videotestsrc num-buffers=3 ! video/x-raw,format=ARGB64 ! projtrack ! fakesink'],
          2, "can't handle caps", f'{name} caps projtrack refuses')
fails([c_binary, 'videotestsrc ! projtrack ! fakesink', 'extra'], 2, 'one pipeline expected',
      'print_features two pipelines')
fails(script('read_roi_meta.py') + ['--pipeline', 'videotestsrc ! projtrack ! fakesink'], 2,
      "named 'tracker'", 'read_roi_meta without a tracker')
fails(script('read_roi_meta.py') + ['--pipeline', 'videotestsrc ! ! fakesink'], 2,
      'cannot build the pipeline', 'read_roi_meta a broken pipeline')

# No plugin: a registry of its own without the build's folder.
with tempfile.TemporaryDirectory() as tmp:
    env = dict(os.environ, GST_PLUGIN_PATH=tmp, GST_REGISTRY_1_0=os.path.join(tmp, 'reg.bin'))
    for cmd in ([c_binary], script('print_features.py'), script('read_roi_meta.py'),
                script('cursor3d.py') + ['--generated']):
        fails(cmd, 2, 'GST_PLUGIN_PATH', f'{os.path.basename(cmd[1] if len(cmd) > 1 else cmd[0])} '
              'without the plugin', env)

# Missing devices, files and packages (`-S`: an interpreter without Debian's packages, as the
# first python3 on PATH may be).
if not os.path.exists('/dev/uinput'):
    fails(script('pointer_uinput.py') + ['--generated', '--frames', '3'], 2,
          'cannot create a uinput device', 'pointer_uinput without /dev/uinput')
fails(script('pointer_uinput.py') + ['--camera', '/nonexistent/video0'], 2, 'no camera at',
      'pointer_uinput without a camera')
fails(script('cursor3d.py') + ['--file', '/nonexistent.mp4'], 2, 'no file', 'cursor3d no file')
fails(script('cursor3d.py') + ['--generated', '--frames', '0'], 2, 'not at least 1',
      'cursor3d --frames 0')
fails(script('demo.py') + ['--frames', '3', '--method', 'nonsense', '--out', tempfile.mkdtemp()],
      2, 'could not set property "method"', 'demo a wrong method')
fails(script('demo.py') + ['--frames', '3', '--out', '/proc/no-such-dir'], 1,
      'No such file or directory', 'demo an unwritable folder')
fails(script('track_numpy.py') + ['--video', '/nonexistent.mp4', '--box', '1,1,5,5'], 2,
      'no file', 'track_numpy no file')
fails(script('track_numpy.py') + ['--video', '/nonexistent.mp4'], 2, 'needs --box or --point',
      'track_numpy a video without a start')
fails(script('track_numpy.py') + ['--box', '1,2'], 2, 'invalid', 'track_numpy a short box')
fails(script('track_numpy.py') + ['--method', 'nonsense'], 2, 'gap-tolerant-filling',
      'track_numpy a wrong method')
fails(script('track_numpy.py') + ['--generated', '--point', '5000,10', '--frames', '2'], 2,
      'lies outside the 640x480 frame', 'track_numpy a point outside')
fails(script('track_several.py') + ['--video', '/nonexistent.mp4'], 2, 'needs --point or --box',
      'track_several a video without a start')
fails(script('track_several.py') + ['--box', '1,2'], 2, 'invalid', 'track_several a short box')
fails(script('track_several.py') + ['--point', '5000,10', '--frames', '2'], 2, 'lies outside',
      'track_several a point outside')
fails(script('track_several.py') + ['--point', '360,170', '--point', '362,172', '--frames', '2'],
      2, 'object 1 is there already', 'track_several two starts on one object')
env = {k: v for k, v in os.environ.items() if k != 'PYTHONPATH'}
fails(script('track_numpy.py') + ['--generated'], 2, 'PYTHONPATH=build/python',
      'track_numpy without the module', env)
fails(script('track_several.py'), 2, 'PYTHONPATH=build/python', 'track_several without the module',
      env)
for name, words in [('print_features.py', 'python3-gst-1.0'), ('read_roi_meta.py', 'python3-gi'),
                    ('cursor3d.py', 'python3-gst-1.0'), ('demo.py', 'python3-numpy'),
                    ('pointer_uinput.py', 'python3-gst-1.0'), ('track_numpy.py', 'python3-opencv'),
                    ('track_several.py', 'python3-opencv')]:
    fails([PY, '-S', os.path.join(EX, name)], 2, words, f'{name} without Debian\'s packages')

# A reader that goes after one line: exit code 0, nothing on stderr.
long_run = ('videotestsrc pattern=ball num-buffers=3000 ! video/x-raw,width=160,height=120 ! '
            'projtrack name=tracker inner-point-x=80 inner-point-y=60 ! fakesink')
for cmd in (script('read_roi_meta.py') + ['--pipeline', long_run],
            script('read_roi_meta.py') + ['--appsink', '--pipeline', long_run],
            script('print_features.py') + [long_run],
            script('pointer_uinput.py') + ['--dry-run', '--generated', '--frames', '60'],
            script('track_numpy.py') + ['--generated', '--frames', '200', '--opencv', 'none']):
    what = ' '.join(os.path.basename(c) for c in cmd[1:3]) + ' | head -1'
    done = first_line_then_close(cmd)
    clean(done, what)
    check(done.stdout.strip() != '', f'{what}: a first line')
    check(done.returncode == 0, f'{what}: exit code 0', f', not {done.returncode}')
    check(done.stderr == '' or 'pointer_uinput' in what, f'{what}: nothing on stderr',
          f': {done.stderr!r}')

print(f'{len(failures)} failures')
sys.exit(1 if failures else 0)
