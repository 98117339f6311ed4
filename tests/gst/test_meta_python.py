#!/usr/bin/python3
"""A Python application reads projtrack's features after videoconvert ! videoscale: GStreamer
1.22's Python cannot map a meta's C struct, but GstProjtrackMeta is a GstCustomMeta, whose
structure it reads (buffer.get_custom_meta(...).get_structure()); the ROI meta of the same track is
found by its id, the track id. Exit status 0 when every frame's meta is there, scaled."""
import sys

import gi
gi.require_version('Gst', '1.0')
gi.require_version('GstVideo', '1.0')
from gi.repository import Gst, GstVideo  # noqa: E402

Gst.init(None)
failures = []
seen = []


def check(ok, what):
    if not ok:
        failures.append(f'frame {len(seen)}: {what}')


def on_buffer(sink, buffer, pad):
    meta = buffer.get_custom_meta('GstProjtrackMeta')
    check(meta is not None, 'a GstProjtrackMeta')
    if meta is not None:
        s = meta.get_structure()
        check(s.get_value('frame-width') == 320 and s.get_value('frame-height') == 240,
              'the frame is 320x240')
        check(s.get_string('element') == 'tracker', "the element's name")
        track = s.get_value('track-id')
        check(track > 0, 'a track id')
        cx, cy = s.get_value('centroid-x'), s.get_value('centroid-y')
        if not seen:  # videotestsrc's ball starts at the centre
            check(abs(cx - 159.75) < 2 and abs(cy - 119.75) < 2, f'centroid {cx}, {cy}')
        outline = [list(p) for p in s.get_value('outline')]
        check(len(outline) >= 1 and len(outline[0]) >= 6, 'an outline')
        check(all(0 <= v < 320 for v in outline[0][0::2]), 'its x in the frame')
        roi = GstVideo.buffer_get_video_region_of_interest_meta_id(buffer, track)
        check(roi is not None and abs(roi.x - s.get_value('x')) <= 1, 'the ROI meta by its id')
    seen.append(buffer.pts)


pipeline = Gst.parse_launch(
    'videotestsrc pattern=ball animation-mode=frames num-buffers=10 ! '
    'video/x-raw,format=I420,width=640,height=480 ! projtrack name=tracker '
    'inner-point-x=320 inner-point-y=240 ! videoconvert ! videoscale ! '
    'video/x-raw,width=320,height=240 ! fakesink name=sink signal-handoffs=true')
pipeline.get_by_name('sink').connect('handoff', on_buffer)
pipeline.set_state(Gst.State.PLAYING)
msg = pipeline.get_bus().timed_pop_filtered(20 * Gst.SECOND,
                                            Gst.MessageType.EOS | Gst.MessageType.ERROR)
check(msg is not None and msg.type == Gst.MessageType.EOS, 'the pipeline ends')
pipeline.set_state(Gst.State.NULL)
check(len(seen) == 10, 'every frame arrived')
for f in failures:
    print('FAIL ' + f)
print(f'{len(seen)} frames, {len(failures)} failures')
sys.exit(1 if failures else 0)
