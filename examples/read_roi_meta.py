#!/usr/bin/python3
"""Reads projtrack's results from the buffers themselves: the GstVideoRegionOfInterestMeta it
attaches to every tracked frame (the object's box, with the features as a 'projtrack' parameter
structure), from a pad probe or from an appsink.

    GST_PLUGIN_PATH=build/gst examples/read_roi_meta.py             # a pad probe
    GST_PLUGIN_PATH=build/gst examples/read_roi_meta.py --appsink   # an app pulling samples
    GST_PLUGIN_PATH=build/gst examples/read_roi_meta.py --pipeline '... ! projtrack name=tracker ! ...'

From Python, buffer.get_meta('GstVideoRegionOfInterestMetaAPI') gives a bare Gst.Meta with no
fields: the ROI meta is reached through GstVideo.buffer_get_video_region_of_interest_meta_id(),
and its roi_type is a GLib quark (GLib.quark_to_string() names it: 'object'). A buffer carries
the meta only while an object is tracked; the parameters' 'status' still says how it was measured.
"""
from cli import (FAILED, USAGE, Failure, gi_modules, gstreamer, parse_launch, parser, play, run,
                 say, wait_for_end)

GLib, Gst, GstVideo = gi_modules('read_roi_meta', 'GLib', 'Gst', 'GstVideo')

DEFAULT_PIPELINE = ('videotestsrc pattern=ball num-buffers=60 ! video/x-raw,width=320,height=240 ! '
                    'projtrack name=tracker inner-point-x=160 inner-point-y=120 ! fakesink')
MEASURED = ('ok', 'reached-border', 'covers-frame')


def projtrack_roi(buffer):
    """(x, y, width, height, params) of the box projtrack attached to `buffer`, or None.

    projtrack attaches a GstProjtrackMeta (a GstCustomMeta: its structure holds the features, kept
    true to the frame through videoconvert and videoscale) and a ROI meta of type 'object' whose id
    is the meta's track-id (GStreamer 1.22's videoscale drops the ROI meta's parameters, never
    GstProjtrackMeta's)."""
    custom = buffer.get_custom_meta('GstProjtrackMeta')
    if custom is None:
        return None
    params = custom.get_structure()
    meta = GstVideo.buffer_get_video_region_of_interest_meta_id(buffer, params.get_value('track-id'))
    if meta is None or GLib.quark_to_string(meta.roi_type) != 'object':
        return None
    return meta.x, meta.y, meta.w, meta.h, params


def describe(buffer):
    """One line for one buffer."""
    when = f'{buffer.pts / Gst.SECOND:8.3f}s' if buffer.pts != Gst.CLOCK_TIME_NONE else '       -'
    roi = projtrack_roi(buffer)
    if roi is None:
        return f'{when} no meta (nothing tracked on this frame)'
    x, y, w, h, p = roi
    status = p.get_string('status')
    if status not in MEASURED:  # never the case today; a reader checks all the same
        return f'{when} {status}'
    return (f'{when} {status:15} box {x},{y} {w}x{h}  centroid ({p.get_value("centroid-x"):7.1f}, '
            f'{p.get_value("centroid-y"):7.1f})  area {p.get_value("area"):.0f} px²')


def run_with_probe(pipeline):
    """Reads every buffer leaving the projtrack element named 'tracker', whatever the sink."""
    tracker = pipeline.get_by_name('tracker')
    if tracker is None:
        raise Failure("the pipeline has no projtrack element named 'tracker' (name=tracker)",
                      USAGE)

    def on_buffer(pad, info):
        say(describe(info.get_buffer()))
        return Gst.PadProbeReturn.OK

    tracker.get_static_pad('src').add_probe(Gst.PadProbeType.BUFFER, on_buffer)
    play(pipeline)
    wait_for_end(pipeline)
    return 0


def run_with_appsink(pipeline_text):
    """An app's way: projtrack's output into an appsink, samples pulled one by one."""
    tail = pipeline_text.rsplit('!', 1)[0]
    pipeline = parse_launch(Gst, tail + '! appsink name=app sync=false')
    sink = pipeline.get_by_name('app')
    play(pipeline)
    try:
        while (sample := sink.emit('pull-sample')) is not None:
            if not say(describe(sample.get_buffer())):
                return 0  # the reader has gone
        error = pipeline.get_bus().pop_filtered(Gst.MessageType.ERROR)
    finally:
        pipeline.set_state(Gst.State.NULL)
    if error:
        raise Failure('pipeline error: ' + error.parse_error()[0].message, FAILED)
    return 0


def main():
    ap = parser(__doc__)
    ap.add_argument('--appsink', action='store_true',
                    help='pull samples from an appsink that replaces the last element')
    ap.add_argument('--pipeline', default=DEFAULT_PIPELINE,
                    help='a pipeline with a projtrack element named tracker')
    args = ap.parse_args()
    gstreamer()
    if args.appsink:
        return run_with_appsink(args.pipeline)
    return run_with_probe(parse_launch(Gst, args.pipeline))


if __name__ == '__main__':
    run('read_roi_meta', main)
