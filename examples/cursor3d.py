#!/usr/bin/python3
"""A 3D cursor: track any evenly coloured object and use it as a pointer — x and y from where it
is, depth from how big it looks, and a quick push toward the camera as a click.

    cursor3d.py                      # the camera (/dev/video0), in a window: wave an object
    cursor3d.py --file clip.mp4      # a file: writes the trajectory plot (--out)
    cursor3d.py --generated          # a generated hand that moves and pushes once

Prints one line per gesture and, for files and generated input, plots the trajectory (x, y and
depth over time, pushes marked) to --out. Needs the plugin on GST_PLUGIN_PATH and Debian's
python3-gst-1.0, python3-numpy and python3-matplotlib.
"""
import argparse
import math
import os
import sys

import gi

gi.require_version('Gst', '1.0')
from gi.repository import GLib, Gst  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def generated_source(pipeline_text_tail, frames):
    """A pipeline fed by appsrc with a hand that drifts right, then pushes once at 2 s."""
    from demo import HandScene  # the demo's generator

    def path(i):
        t = i / 30
        push = 0.3 * math.sin(math.pi * (t - 2.0) / 0.4) if 2.0 < t < 2.4 else 0.0
        return 0.35 + 0.1 * t / 4, 0.55, 1.0 + push

    scene = HandScene(640, 480, path)
    pipeline = Gst.parse_launch(
        'appsrc name=src format=time caps=video/x-raw,format=RGBx,width=640,height=480,'
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
    import matplotlib
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    src = ap.add_mutually_exclusive_group()
    src.add_argument('--camera', default='/dev/video0', help='V4L2 device (default)')
    src.add_argument('--file', help='a video file')
    src.add_argument('--generated', action='store_true', help='a generated hand')
    ap.add_argument('--frames', type=int, default=120, help='with --generated')
    ap.add_argument('--out', default='out/trajectory.png', help='the plot, for files')
    args = ap.parse_args()
    Gst.init(None)

    tracker = 'projtrack name=tracker acquisition=auto'
    feed = None
    if args.generated:
        pipeline, feed = generated_source(tracker + ' ! fakesink', args.frames)
    elif args.file:
        pipeline = Gst.parse_launch(f'filesrc location="{args.file}" ! decodebin ! videoconvert ! '
                                    f'{tracker} ! fakesink')
    else:
        pipeline = Gst.parse_launch(f'v4l2src device={args.camera} ! videoconvert ! {tracker} '
                                    'draw=true ! videoconvert ! autovideosink')
    samples, pushes, state = [], [], {}
    loop = GLib.MainLoop()

    def on_message(bus, msg):
        if msg.type == Gst.MessageType.ERROR:
            print('error:', msg.parse_error()[0].message, file=sys.stderr)
            loop.quit()
        elif msg.type == Gst.MessageType.EOS:
            loop.quit()
        elif msg.type == Gst.MessageType.ELEMENT and msg.get_structure().get_name() == 'projtrack':
            s = msg.get_structure()
            t = s.get_value('timestamp') / Gst.SECOND
            if s.has_field('depth') and s.get_string('status') != 'lost':
                samples.append((t, s.get_value('position-x'), s.get_value('position-y'),
                                s.get_value('depth')))
            if s.has_field('acquired'):
                print(f'{t:7.2f}s  acquired an object', flush=True)
            if s.get_string('status') == 'lost' and not state.get('lost'):
                print(f'{t:7.2f}s  lost: {s.get_string("detail")}', flush=True)
            state['lost'] = s.get_string('status') == 'lost'
            if s.has_field('gesture'):
                pushes.append(t)
                print(f'{t:7.2f}s  {s.get_string("gesture")}  at x {s.get_value("position-x"):+.2f} '
                      f'y {s.get_value("position-y"):+.2f} depth {s.get_value("depth"):.2f}',
                      flush=True)
        return True

    bus = pipeline.get_bus()
    bus.add_signal_watch()
    bus.connect('message', on_message)
    pipeline.set_state(Gst.State.PLAYING)
    if feed:
        GLib.idle_add(lambda: feed() and False)
    try:
        loop.run()
    except KeyboardInterrupt:
        pass
    pipeline.set_state(Gst.State.NULL)
    if (args.file or args.generated) and samples:
        os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
        plot(samples, pushes, args.out)
        print(f'{len(samples)} frames tracked, {len(pushes)} push(es); wrote {args.out}')
    return 0 if samples else 1


if __name__ == '__main__':
    sys.exit(main())
