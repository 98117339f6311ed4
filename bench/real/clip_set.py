"""The development set of real footage: which clips, in which Debian package, where each
file lies in it, and which variants each clip is run with. One table, read by prepare.py (the
plan projtrack-real runs), by the report and by the accuracy test.

A clip's file is looked for under the folder its package was unpacked into (`dpkg -x`; the run
script caches python3-mecavideo and visp-images-data under <build dir>/real-clips/root), then at
the same path under / (an installed package: opencv-doc).
"""
import collections
import glob
import os

Clip = collections.namedtuple("Clip", "name package path kind thrown what")

OCV = "usr/share/doc/opencv-doc/"
MECA = "usr/share/pymecavideo/data/video/"
VISP = "usr/share/visp-images-data/ViSP-images/"

# kind: 'video' (a file GStreamer's decodebin reads), 'video.gz' (gzipped: unpacked once into the
# data folder), 'pgm' (a numbered sequence of grey images), 'opencv' (a file GStreamer 1.22
# cannot demux, VP9 in AVI: read by OpenCV's FFmpeg reader; projtrack-real's clip.hpp).
CLIPS = [
    Clip("cup", "opencv-doc", OCV + "opencv4/html/cup.mp4.gz", "video.gz", False,
         "a hand turning a dark printed cup"),
    Clip("box", "opencv-doc", OCV + "opencv4/html/box.mp4.gz", "video.gz", False,
         "a hand turning a printed box"),
    Clip("vtest", "opencv-doc", OCV + "examples/data/vtest.avi", "video", False,
         "people walking across a square"),
    Clip("megamind", "opencv-doc", OCV + "examples/data/Megamind.avi", "video", False,
         "a cartoon face, with cuts"),
    Clip("balle1", "python3-mecavideo", MECA + "balle1-vp9.avi", "opencv", True,
         "a small red ball thrown across a classroom"),
    Clip("inertie", "python3-mecavideo", MECA + "Principe_inertie.avi", "video", False,
         "a puck sliding over a table"),
    Clip("force", "python3-mecavideo", MECA + "Force_constante.avi", "video", False,
         "a puck pulled over a table"),
    Clip("magnet", "python3-mecavideo", MECA + "Effet_force_magnetique.ogv", "video", False,
         "a puck deflected by a magnet"),
    Clip("cube", "visp-images-data", VISP + "mbt/cube/image*.pgm", "pgm", False,
         "a printed cube on a table, moving camera, a hand enters"),
    Clip("ellipse", "visp-images-data", VISP + "ellipse-1/image.*.pgm", "pgm", False,
         "a white ellipse leaving through the frame's edge"),
]
BY_NAME = {c.name: c for c in CLIPS}

# The variants (made by projtrack-real from the decoded frames; their truth by prepare.py):
#   edge   the frame cropped on the first in-view frame so that the nearest frame edge cuts
#          EDGE_CUT of the object's box off (the crop is kept for the whole clip)
#   half   half size (INTER_AREA)
#   mirror, dark, dim, bright, gamma, warm, noise, fast: the lighting, noise and speed variants
#          (their settings are projtrack-real's, recorded in meta.json)
EDGE_CUT = 0.25
GEOMETRIC = ["edge", "half", "mirror", "fast"]
ALL_VARIANTS = ["edge", "half", "mirror", "dark", "dim", "bright", "gamma", "warm", "noise",
                "fast"]
# The whole run must stay within about an hour on two cores: every variant on clips up to
# LONG_FRAMES frames, and on longer ones the two the issue asks for (edge, half) with one light
# and one noise variant.
LONG_FRAMES = 300
LONG_VARIANTS = ["edge", "half", "dim", "noise"]


def variants_for(frames):
    """The variants a clip of `frames` in-view-trimmed frames is run with."""
    return ALL_VARIANTS if frames <= LONG_FRAMES else LONG_VARIANTS


def resolve(clip, root):
    """The path of the clip's file (for 'pgm', its sorted image paths' pattern) under `root`, or
    under / when it is not there; None when neither holds it."""
    for base in ([root] if root else []) + ["/"]:
        path = os.path.join(base, clip.path)
        if clip.kind == "pgm":
            if glob.glob(path):
                return path
        elif os.path.exists(path):
            return path
    return None


def pgm_files(pattern):
    """A pgm sequence's images in the order they are played (sorted by name, as the labels)."""
    return sorted(glob.glob(pattern))
