"""What every example shares: one command-line style and clean failures.

- argparse, with the example's docstring as its --help;
- an error the user can act on is `prog: message` on stderr and an exit code, never a
  traceback: 2 for a bad argument or a missing package, plugin or device (argparse's own code
  for a bad argument), 1 for a run that failed (a pipeline error, nothing tracked), 130 for
  Ctrl-C;
- output that its reader closes early (`| head`) ends the run quietly, with exit code 0: the
  reader had what it wanted.
"""
import argparse
import importlib
import os
import sys
import threading

USAGE = 2
FAILED = 1


class Failure(Exception):
    """An error with a message for the user and the exit code it ends the run with."""

    def __init__(self, message, code=FAILED):
        super().__init__(message)
        self.code = code


def parser(doc):
    """The argument parser of an example whose module docstring is `doc`: the first line
    describes it, the rest (its usage lines) follows --help's options."""
    first, _, rest = doc.strip().partition('\n')
    return argparse.ArgumentParser(description=first, epilog=rest.strip() or None,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)


def positive_int(text):
    """An argparse type: an integer of at least 1."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f'{text!r} is not a whole number') from None
    if value < 1:
        raise argparse.ArgumentTypeError(f'{value} is not at least 1')
    return value


# Set once stdout's reader has gone: a pipeline's streaming threads stop printing, and the
# example ends its run.
stdout_closed = threading.Event()


def _silence_stdout():
    """Points stdout at /dev/null, so that no later write or the interpreter's last flush fails."""
    stdout_closed.set()
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except OSError:
        pass


def say(text='', end='\n'):
    """Prints `text` at once; False (and nothing printed) once stdout's reader has gone.
    Safe from any thread, where an exception would only be printed and not end the run."""
    if stdout_closed.is_set():
        return False
    try:
        print(text, end=end, flush=True)
        return True
    except BrokenPipeError:
        _silence_stdout()
        return False


def run(prog, main):
    """Runs main() (its return value the exit code) and exits, turning a Failure, Ctrl-C and a
    closed stdout into a message and an exit code."""
    try:
        code = main()
    except Failure as e:
        print(f'{prog}: {e}', file=sys.stderr)
        code = e.code
    except KeyboardInterrupt:
        print(f'{prog}: interrupted', file=sys.stderr)
        code = 130
    except BrokenPipeError:
        _silence_stdout()
        code = 0
    except OSError as e:  # a file that cannot be read or written, a device that is not there
        print(f'{prog}: {e}', file=sys.stderr)
        code = FAILED
    if stdout_closed.is_set():
        code = 0
    try:
        sys.stdout.flush()
    except BrokenPipeError:
        _silence_stdout()
    sys.exit(code)


GI_VERSIONS = {'Gst': '1.0', 'GstVideo': '1.0', 'GstApp': '1.0'}


def missing(prog, what, package, hint=None):
    """Exits (USAGE) saying that `what` cannot be imported, and how to get it: `hint`, or
    Debian's interpreter with `package`."""
    hint = hint or (f"run with Debian's /usr/bin/python3 (the examples' first line) and "
                    f"install {package}")
    print(f'{prog}: cannot import {what}: {hint}', file=sys.stderr)
    sys.exit(USAGE)


def gi_modules(prog, *names):
    """The GObject-introspection modules `names` ('GLib', 'Gst', 'GstVideo'), imported; exits
    (USAGE) naming the packages when they are missing: the first python3 on PATH may be another
    interpreter than Debian's."""
    try:
        import gi
        for name in names:
            if name in GI_VERSIONS:
                gi.require_version(name, GI_VERSIONS[name])
        return tuple(importlib.import_module('gi.repository.' + name) for name in names)
    except (ImportError, ValueError) as e:
        missing(prog, f"GStreamer's Python bindings ({e})",
                'python3-gi, python3-gst-1.0 and gir1.2-gst-plugins-base-1.0')


def module(prog, name, package, hint=None):
    """Python module `name`, imported; exits (USAGE) naming its Debian package (or saying
    `hint`) when it is missing."""
    try:
        return importlib.import_module(name)
    except ImportError as e:
        missing(prog, f'the Python module {name} ({e})', package, hint)


def gstreamer(need_projtrack=True):
    """Gst, initialised; a Failure (USAGE) when the projtrack plugin cannot be found."""
    (Gst,) = gi_modules(os.path.basename(sys.argv[0]), 'Gst')
    Gst.init(None)
    if need_projtrack and Gst.ElementFactory.find('projtrack') is None:
        raise Failure('no projtrack element: point GST_PLUGIN_PATH at the build\'s plugin '
                      '(GST_PLUGIN_PATH=$PWD/build/gst) or install it', USAGE)
    return Gst


def parse_launch(Gst, description):
    """The pipeline `description` says, as a Gst.Pipeline; a Failure (USAGE) saying what is wrong
    with it."""
    from gi.repository import GLib
    try:
        element = Gst.parse_launch(description)
    except GLib.Error as e:
        raise Failure(f'cannot build the pipeline: {e.message}', USAGE) from None
    if not isinstance(element, Gst.Pipeline):  # one element alone: no bus of its own
        pipeline = Gst.Pipeline.new(None)
        pipeline.add(element)
        element = pipeline
    if not any(e.get_factory() and e.get_factory().get_name() == 'projtrack'
               for e in iterate(element.iterate_recurse())):
        raise Failure('the pipeline has no projtrack element', USAGE)
    return element


def iterate(it):
    """The items of a Gst.Iterator."""
    items = []
    it.foreach(items.append)
    return items


def error_text(msg):
    """The text of an error message on the bus: the element that posted it, and what it says."""
    err, _ = msg.parse_error()
    where = msg.src.get_name() if msg.src else ''
    return f'{where}: {err.message}' if where else err.message


def play(pipeline):
    """Sets `pipeline` playing; a Failure with the bus's error when it cannot start."""
    from gi.repository import Gst
    if pipeline.set_state(Gst.State.PLAYING) == Gst.StateChangeReturn.FAILURE:
        msg = pipeline.get_bus().pop_filtered(Gst.MessageType.ERROR)
        pipeline.set_state(Gst.State.NULL)
        raise Failure('the pipeline cannot start' + (f': {error_text(msg)}' if msg else ''))


def wait_for_end(pipeline, on_message=None, types=None):
    """Waits for the end of stream, an error or stdout's reader to go, passing every message of
    `types` to on_message(msg); stops the pipeline. A Failure on an error."""
    from gi.repository import Gst
    bus = pipeline.get_bus()
    wanted = Gst.MessageType.EOS | Gst.MessageType.ERROR
    if types:
        wanted |= types
    try:
        while not stdout_closed.is_set():
            msg = bus.timed_pop_filtered(100 * Gst.MSECOND, wanted)
            if msg is None:
                continue
            if msg.type == Gst.MessageType.ERROR:
                raise Failure(f'pipeline error: {error_text(msg)}')
            if msg.type == Gst.MessageType.EOS:
                return
            if on_message:
                on_message(msg)
    finally:
        pipeline.set_state(Gst.State.NULL)
