#!/usr/bin/python3
"""The tracked object as the system's pointer, the paper's "3D cursor-like input device": x and y
move the pointer over the screen, a push toward the camera clicks, a push held is a drag (the
button down until the object comes back). Through Linux's uinput, with Debian's python3-evdev;
the new device is an absolute pointer (a tablet, to the desktop).

    sudo pointer_uinput.py                     # the camera (/dev/video0), mirrored like a mirror
    pointer_uinput.py --dry-run --generated    # print the events instead of sending them
    pointer_uinput.py --dry-run --file clip.mp4

Writing to /dev/uinput needs root or the uinput group. --dry-run opens no device: it prints each
event it would send (its evdev name and value), and is what the tests run. Exit code 0 when the
pointer moved, 1 when it never did or the pipeline failed, 2 without a camera, uinput device or
package it needs.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli import USAGE, Failure, gstreamer, module, parser, run, say  # noqa: E402
from cursor3d import (TRACKING, add_source_arguments, camera_problem,  # noqa: E402
                      run_pipeline, source_pipeline)

evdev = module('pointer_uinput', 'evdev', 'python3-evdev')
AbsInfo, UInput, ecodes = evdev.AbsInfo, evdev.UInput, evdev.ecodes

AXIS_MAX = 65535  # the device's absolute range on both axes; the desktop maps it to the screen
# The left button's values for each gesture of the element's `gesture` field: a push is a click
# (down and up: two pushes are a double click), a press holds the button down (a drag while the
# object moves), a release lets it up (also sent when the track ends while pressed).
BUTTON = {'push': (1, 0), 'press': (1,), 'release': (0,)}


class DryRun:
    """Stands in for UInput: prints every event and every report."""

    def write(self, kind, code, value):
        name = ecodes.bytype[kind][code]
        say(f'{ecodes.EV[kind]} {name if isinstance(name, str) else name[0]} {value}')

    def syn(self):
        say('SYN_REPORT')

    def close(self):
        pass


def open_device(dry_run):
    if dry_run:
        return DryRun()
    axis = AbsInfo(value=AXIS_MAX // 2, min=0, max=AXIS_MAX, fuzz=0, flat=0, resolution=0)
    return UInput({ecodes.EV_ABS: [(ecodes.ABS_X, axis), (ecodes.ABS_Y, axis)],
                   ecodes.EV_KEY: [ecodes.BTN_LEFT]}, name='projtrack 3D pointer')


def to_axis(position):
    """A position in [-1, 1] (the element's position-x or -y) to the device's range."""
    return round((min(max(position, -1.0), 1.0) + 1) / 2 * AXIS_MAX)


def main():
    ap = parser(__doc__)
    add_source_arguments(ap)
    ap.add_argument('--dry-run', action='store_true', help='print the events, open no device')
    ap.add_argument('--mirror', action=argparse.BooleanOptionalAction, default=None,
                    help='move left when the object moves right in the picture (default: for '
                         'a camera, which faces its user)')
    args = ap.parse_args()
    camera = not (args.file or args.generated)
    if camera and (why := camera_problem(args.camera)):
        raise Failure(f'{why}: use --file or --generated', USAGE)
    mirror = camera if args.mirror is None else args.mirror
    gstreamer()
    pipeline, feed = source_pipeline(args, 'projtrack name=tracker', '! fakesink')
    try:
        device = open_device(args.dry_run)
    except (OSError, evdev.UInputError) as e:
        raise Failure(f'cannot create a uinput device ({e}): load the uinput module '
                      '(modprobe uinput), run as root or join the uinput group; --dry-run '
                      'prints the events instead', USAGE) from None
    moved = [0]

    def on_projtrack(s):
        if s.get_string('status') in TRACKING:  # lost, searching: the pointer stays
            x = s.get_value('position-x')
            device.write(ecodes.EV_ABS, ecodes.ABS_X, to_axis(-x if mirror else x))
            device.write(ecodes.EV_ABS, ecodes.ABS_Y, to_axis(s.get_value('position-y')))
            device.syn()
            moved[0] += 1
        for value in BUTTON.get(s.get_string('gesture'), ()):  # whatever the status: a release
            device.write(ecodes.EV_KEY, ecodes.BTN_LEFT, value)  # must come when the track ends
            device.syn()

    try:
        run_pipeline(pipeline, feed, on_projtrack)
    finally:
        device.close()
    print(f'pointer_uinput: moved the pointer on {moved[0]} frames', file=sys.stderr)
    return 0 if moved[0] else 1


if __name__ == '__main__':
    run('pointer_uinput', main)
