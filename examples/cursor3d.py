#!/usr/bin/python3
"""A 3D cursor: track any evenly coloured object and use it as a pointer — x and y from where it
is, depth from how big it looks, and a quick push toward the camera as a click.

    cursor3d.py                      # the camera (/dev/video0), in a window: wave an object
    cursor3d.py --file clip.mp4      # a file: writes the trajectory CSV and plot (--csv, --out)
    cursor3d.py --generated          # a generated hand that moves and pushes once

Prints a live line with x, y, depth and the status (rewritten in place on a terminal; --live
forces it), one line per event (acquired, lost and why, push), and, for files and generated
input, writes every frame to a CSV (--csv) and plots the trajectory (x, y and depth over time,
pushes marked) to --out. Without a camera it says so and exits; without a display the camera's
picture is not shown. Needs the plugin on GST_PLUGIN_PATH and Debian's python3-gst-1.0,
python3-numpy and python3-matplotlib. Exit code 0 when an object was tracked, 1 when none was
or the pipeline failed, 2 without a camera, file or package it needs.
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli import (USAGE, Failure, gi_modules, gstreamer, module, parse_launch,  # noqa: E402
                 parser, positive_int, run, say, stdout_closed)

GLib, Gst = gi_modules(os.path.basename(sys.argv[0]), 'GLib', 'Gst')


def generated_source(pipeline_text_tail, frames):
    """A pipeline fed by appsrc with a hand that drifts right, then pushes once at 2 s."""
    from demo import HandScene  # the demo's generator

    def path(i):
        t = i / 30
        push = 0.3 * math.sin(math.pi * (t - 2.0) / 0.4) if 2.0 < t < 2.4 else 0.0
        return 0.35 + 0.1 * t / 4, 0.55, 1.0 + push

    scene = HandScene(640, 480, path)
    pipeline = parse_launch(
        Gst, 'appsrc name=src format=time caps=video/x-raw,format=RGBx,width=640,height=480,'
        'framerate=30/1 ! videoconvert ! ' + pipeline_text_tail)
    src = pipeline.get_by_name('src')

    def feed():
        for i in range(frames):
            buf = Gst.Buffer.new_wrapped(scene.frame(scene.mask(i)).tobytes())
            buf.pts, buf.duration = i * Gst.SECOND // 30, Gst.SECOND // 30
            src.emit('push-buffer', buf)
        src.emit('end-of-stream')
    return pipeline, feed


def plot(samples, pushes, path):
    matplotlib = module('cursor3d', 'matplotlib', 'python3-matplotlib')
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    t = [s[0] for s in samples]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.5))
    sc = ax1.scatter([s[1] for s in samples], [s[2] for s in samples], c=t, s=8, cmap='viridis')
    ax1.set_xlim(-1, 1)
    ax1.set_ylim(1, -1)  # image convention: y grows downwards
    ax1.set_xlabel('x')
    ax1.set_ylabel('y')
    ax1.set_title('where the cursor went')
    fig.colorbar(sc, ax=ax1, label='s')
    ax2.plot(t, [s[3] for s in samples], label='depth')
    ax2.plot(t, [s[1] for s in samples], label='x', alpha=0.6)
    ax2.plot(t, [s[2] for s in samples], label='y', alpha=0.6)
    for p in pushes:
        ax2.axvline(p, color='red', linestyle='--')
    ax2.set_xlabel('s')
    ax2.set_title('x, y and depth over time (pushes dashed)')
    ax2.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=90)


TRACKING = ('ok', 'reached-border', 'covers-frame')  # statuses whose features are measured
CSV_FIELDS = ['time', 'status', 'x', 'y', 'depth', 'centroid_x', 'centroid_y', 'area', 'gesture',
              'detail']


def camera_problem(device):
    """Why `device` cannot be a camera, or None: checked before GStreamer opens it."""
    if not os.path.exists(device):
        return f'no camera at {device}'
    if not os.access(device, os.R_OK | os.W_OK):
        return f'{device} is not readable and writable by this user (the video group?)'
    return None


def has_display():
    return bool(os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY'))


def row(s):
    """One CSV row of one projtrack message: measured features only while tracking."""
    status = s.get_string('status')
    r = {'time': f'{s.get_value("timestamp") / Gst.SECOND:.3f}', 'status': status,
         'gesture': s.get_string('gesture') or '', 'detail': s.get_string('detail') or ''}
    if status in TRACKING:
        r.update(x=f'{s.get_value("position-x"):.4f}', y=f'{s.get_value("position-y"):.4f}',
                 depth=f'{s.get_value("depth"):.4f}', centroid_x=f'{s.get_value("centroid-x"):.2f}',
                 centroid_y=f'{s.get_value("centroid-y"):.2f}', area=f'{s.get_value("area"):.0f}')
    return r


def live_line(s):
    """The live line: x, y and depth while tracking, else the status and why."""
    status = s.get_string('status')
    if status in TRACKING:
        return (f'x {s.get_value("position-x"):+.2f}  y {s.get_value("position-y"):+.2f}  '
                f'depth {s.get_value("depth"):.2f}  {status}')
    return f'{status}: {s.get_string("detail") or ""}'


def add_source_arguments(ap):
    """--camera (the default), --file or --generated, and --frames: shared with
    pointer_uinput.py."""
    src = ap.add_mutually_exclusive_group()
    src.add_argument('--camera', default='/dev/video0', help='V4L2 device (default)')
    src.add_argument('--file', help='a video file')
    src.add_argument('--generated', action='store_true', help='a generated hand')
    ap.add_argument('--frames', type=positive_int, default=120, help='with --generated')


def source_pipeline(args, tracker, camera_tail):
    """(pipeline, feed): the source the arguments name into `tracker` (a projtrack element and
    what follows it: `camera_tail` after a camera, fakesink after a file or generated frames);
    `feed` pushes the generated frames (None for the others)."""
    if args.generated:
        return generated_source(f'{tracker} ! fakesink', args.frames)
    if args.file:
        if not os.path.isfile(args.file):
            raise Failure(f'no file {args.file}', USAGE)
        return parse_launch(Gst, f'filesrc location="{args.file}" ! decodebin ! videoconvert ! '
                                 f'{tracker} ! fakesink'), None
    return parse_launch(Gst, f'v4l2src device={args.camera} ! videoconvert ! {tracker} '
                             f'{camera_tail}'), None


def run_pipeline(pipeline, feed, on_projtrack):
    """Plays `pipeline` until its end, Ctrl-C or stdout's reader going, calling
    on_projtrack(structure) for every projtrack message; a Failure on a pipeline error."""
    loop = GLib.MainLoop()
    errors = []  # a pipeline error, or what on_projtrack raised: raised once the loop is left

    def on_message(bus, msg):
        if msg.type == Gst.MessageType.ERROR:
            errors.append(Failure(f'pipeline error: {msg.src.get_name()}: '
                                  f'{msg.parse_error()[0].message}'))
            loop.quit()
        elif msg.type == Gst.MessageType.EOS:
            loop.quit()
        elif msg.type == Gst.MessageType.ELEMENT and msg.get_structure().get_name() == 'projtrack':
            try:
                on_projtrack(msg.get_structure())
            except Exception as e:  # noqa: BLE001 -- a callback's exception would only be printed
                errors.append(e)
                loop.quit()
        return True

    def reader_gone():
        if stdout_closed.is_set():
            loop.quit()
        return True

    bus = pipeline.get_bus()
    bus.add_signal_watch()
    bus.connect('message', on_message)
    GLib.timeout_add(100, reader_gone)
    pipeline.set_state(Gst.State.PLAYING)
    if feed:
        GLib.idle_add(lambda: feed() and False)
    try:
        loop.run()
    except KeyboardInterrupt:
        pass
    finally:
        pipeline.set_state(Gst.State.NULL)
        bus.remove_signal_watch()
    if errors:
        raise errors[0]


def main():
    ap = parser(__doc__)
    add_source_arguments(ap)
    ap.add_argument('--out', default='out/trajectory.png', help='the plot, for files')
    ap.add_argument('--csv', default='out/trajectory.csv', help='every frame, for files')
    ap.add_argument('--live', action='store_true',
                    help='print the live line even when the output is not a terminal')
    args = ap.parse_args()
    camera = not (args.file or args.generated)
    if camera and (why := camera_problem(args.camera)):
        raise Failure(f'{why}: plug one in, or use --file clip.mp4 or --generated', USAGE)
    gstreamer()
    live = args.live or sys.stdout.isatty()

    # A camera's picture with the overlay in a window, when there is a display to open one on.
    sink = 'videoconvert ! autovideosink' if has_display() else 'fakesink'
    pipeline, feed = source_pipeline(args, 'projtrack name=tracker acquisition=auto',
                                     f'draw=true ! {sink}')
    samples, pushes, state = [], [], {}
    writer = None
    if not camera:
        os.makedirs(os.path.dirname(os.path.abspath(args.csv)), exist_ok=True)
        csv_file = open(args.csv, 'w', newline='')
        writer = csv.DictWriter(csv_file, CSV_FIELDS)
        writer.writeheader()

    def event(text):
        """An event on its own line (after the live line, if one is shown)."""
        say(('\r\033[K' if live else '') + text)

    def on_projtrack(s):
        t = s.get_value('timestamp') / Gst.SECOND
        status = s.get_string('status')
        if writer:
            writer.writerow(row(s))
        # A lost message holds the last features: only a tracking status is a measurement.
        if status in TRACKING:
            samples.append((t, s.get_value('position-x'), s.get_value('position-y'),
                            s.get_value('depth')))
        if s.has_field('acquired'):
            event(f'{t:7.2f}s  acquired an object')
        if status == 'lost' and not state.get('lost'):
            event(f'{t:7.2f}s  lost: {s.get_string("detail")}')
        state['lost'] = status == 'lost'
        if s.has_field('gesture') and status in TRACKING:
            pushes.append(t)
            event(f'{t:7.2f}s  {s.get_string("gesture")}  at x {s.get_value("position-x"):+.2f} '
                f'y {s.get_value("position-y"):+.2f} depth {s.get_value("depth"):.2f}')
        if live:
            say(f'\r\033[K{t:7.2f}s  {live_line(s)}', end='')

    try:
        run_pipeline(pipeline, feed, on_projtrack)
    finally:
        if writer:
            csv_file.close()
    if live:
        say()
    if not camera and samples:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        plot(samples, pushes, args.out)
        say(f'{len(samples)} frames tracked, {len(pushes)} push(es); wrote {args.csv} and '
            f'{args.out}')
    return 0 if samples else 1


if __name__ == '__main__':
    run('cursor3d', main)
