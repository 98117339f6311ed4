#!/usr/bin/python3
"""Prints the centroid and area that projtrack measures on every frame.

Run with Debian's Python (it has python3-gst-1.0) and the plugin on GST_PLUGIN_PATH:

    GST_PLUGIN_PATH=build/gst examples/print_features.py
    GST_PLUGIN_PATH=build/gst examples/print_features.py \\
        'filesrc location=clip.mp4 ! decodebin ! videoconvert ! projtrack inner-point-x=320 inner-point-y=240 ! fakesink'

The pipeline must contain a projtrack element; its 'projtrack' element messages are read from the
bus (docs/element.md lists every field).
"""
import sys

import gi

gi.require_version('Gst', '1.0')
from gi.repository import Gst  # noqa: E402

DEFAULT_PIPELINE = ('videotestsrc pattern=ball num-buffers=60 ! video/x-raw,width=320,height=240 ! '
                    'projtrack inner-point-x=160 inner-point-y=120 ! fakesink')


# Only these statuses carry features measured on this frame. A 'lost' message repeats the last
# measured ones (so that an app can hold its pointer): never read them as a measurement.
MEASURED = ('ok', 'reached-border', 'covers-frame')


def describe(s):
    """One line for one 'projtrack' message structure."""
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
    Gst.init(None)
    pipeline = Gst.parse_launch(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_PIPELINE)
    bus = pipeline.get_bus()
    pipeline.set_state(Gst.State.PLAYING)
    try:
        return print_messages(bus)
    finally:
        pipeline.set_state(Gst.State.NULL)


def print_messages(bus):
    """Prints every projtrack message until end of stream; 1 on a pipeline error."""
    while True:
        msg = bus.timed_pop_filtered(
            Gst.CLOCK_TIME_NONE,
            Gst.MessageType.ELEMENT | Gst.MessageType.EOS | Gst.MessageType.ERROR)
        if msg.type == Gst.MessageType.ERROR:
            err, _ = msg.parse_error()
            print(f'error: {err.message}', file=sys.stderr)
            return 1
        if msg.type == Gst.MessageType.EOS:
            return 0
        s = msg.get_structure()
        if s is not None and s.get_name() == 'projtrack':
            print(describe(s), flush=True)


if __name__ == '__main__':
    sys.exit(main())
