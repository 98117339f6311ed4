#!/usr/bin/python3
"""Prints the centroid and area that projtrack measures on every frame.

Run with Debian's Python (it has python3-gst-1.0) and the plugin on GST_PLUGIN_PATH:

    GST_PLUGIN_PATH=build/gst examples/print_features.py
    GST_PLUGIN_PATH=build/gst examples/print_features.py \\
        'filesrc location=clip.mp4 ! decodebin ! videoconvert ! projtrack inner-point-x=320 inner-point-y=240 ! fakesink'

The pipeline must contain a projtrack element; its 'projtrack' element messages are read from the
bus (docs/element.md lists every field). Exit code 0 at the end of the stream, 1 on a pipeline
error, 2 for a pipeline that cannot be built.
"""
from cli import FAILED, gstreamer, parse_launch, parser, play, run, say, wait_for_end

DEFAULT_PIPELINE = ('videotestsrc pattern=ball num-buffers=60 ! video/x-raw,width=320,height=240 ! '
                    'projtrack inner-point-x=160 inner-point-y=120 ! fakesink')


# Only these statuses carry features measured on this frame. A 'lost' message repeats the last
# measured ones (so that an app can hold its pointer): never read them as a measurement.
MEASURED = ('ok', 'reached-border', 'covers-frame')


def describe(s):
    """One line for one 'projtrack' message structure."""
    from gi.repository import Gst
    ts = s.get_value('timestamp')
    when = f'{ts / Gst.SECOND:8.3f}s' if ts != Gst.CLOCK_TIME_NONE else '       -'
    status = s.get_string('status')
    if status not in MEASURED:  # nothing measured: the status says why
        return f'{when} {status:15} {s.get_string("detail") or ""}'
    return (f'{when} {status:15} centroid ({s.get_value("centroid-x"):7.1f}, '
            f'{s.get_value("centroid-y"):7.1f})  area {s.get_value("area"):9.0f} px²  '
            f'box {s.get_value("width")}x{s.get_value("height")}  '
            f'{s.get_value("processing-time") / 1e6:.2f} ms')


def main():
    ap = parser(__doc__)
    ap.add_argument('pipeline', nargs='?', default=DEFAULT_PIPELINE,
                    help='a gst-launch-1.0 pipeline with a projtrack element '
                         '(default: videotestsrc\'s ball)')
    args = ap.parse_args()
    Gst = gstreamer()
    pipeline = parse_launch(Gst, args.pipeline)
    seen = []

    def on_message(msg):
        s = msg.get_structure()
        if s is not None and s.get_name() == 'projtrack':
            seen.append(True)
            say(describe(s))

    play(pipeline)
    wait_for_end(pipeline, on_message, Gst.MessageType.ELEMENT)
    return 0 if seen else FAILED


if __name__ == '__main__':
    run('print_features', main)
