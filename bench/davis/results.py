"""A DAVIS run's data (run.py's frames.csv, runs.csv, meta.json) as the report reads it: per run
(sequence, tracker, start) the means over its scored frames, and per (tracker, start) the means
over sequences. A run that was not measured, or a mean over sequences one of which was not, is NaN
(the report writes it "not measured", never a zero)."""
import collections
import csv
import json
import math
import os
import platform

NAN = math.nan

# (tracker, start): how the report names the run, in its order.
LABELS = collections.OrderedDict([
    (("projtrack", "mask"), "projtrack, first mask"),
    (("projtrack", "box"), "projtrack, box"),
    (("projtrack", "click"), "projtrack, click"),
    (("hold", "mask"), "first mask held still"),
    (("CSRT", "box"), "OpenCV CSRT, box"),
    (("KCF", "box"), "OpenCV KCF, box"),
    (("MOSSE", "box"), "OpenCV MOSSE, box"),
    (("MedianFlow", "box"), "OpenCV MedianFlow, box"),
])
# The tables' column heads.
SHORT = {("projtrack", "mask"): "projtrack mask", ("projtrack", "box"): "projtrack box",
         ("projtrack", "click"): "projtrack click", ("hold", "mask"): "held mask",
         ("CSRT", "box"): "CSRT", ("KCF", "box"): "KCF", ("MOSSE", "box"): "MOSSE",
         ("MedianFlow", "box"): "MedianFlow"}
MEASURES = ("j", "f", "kept", "ms")


def mean(values):
    values = list(values)
    return sum(values) / len(values) if values else NAN


def median(values):
    values = sorted(values)
    n = len(values)
    if not n:
        return NAN
    return values[n // 2] if n % 2 else (values[n // 2 - 1] + values[n // 2]) / 2


class Results:
    def __init__(self, data_dir):
        self.dir = data_dir
        with open(os.path.join(data_dir, "meta.json")) as f:
            self.meta = json.load(f)
        self.sequences = self.meta["sequences"]
        with open(os.path.join(data_dir, "runs.csv")) as f:
            self.runs = {(r["sequence"], r["tracker"], r["start"]): r for r in csv.DictReader(f)}
        self.frames = collections.defaultdict(list)  # (sequence, tracker, start): rows
        with open(os.path.join(data_dir, "frames.csv")) as f:
            for r in csv.DictReader(f):
                self.frames[(r["sequence"], r["tracker"], r["start"])].append(r)
        self.keys = [k for k in LABELS if any((s,) + k in self.runs for s in self.sequences)]

    def measured(self, seq, key):
        r = self.runs.get((seq,) + key)
        return bool(r and r["measured"] == "1" and self.frames.get((seq,) + key))

    def note(self, key):
        """Why a run was not measured (the first sequence's word), or ''."""
        for s in self.sequences:
            r = self.runs.get((s,) + key)
            if r and r["measured"] != "1":
                return r["note"]
        return ""

    def per_frame(self, seq, key, measure):
        """{frame: value} of one run (ms: only frames where the tracker was called)."""
        out = {}
        for r in self.frames.get((seq,) + key, []):
            if r[measure] != "":
                out[int(r["frame"])] = float(r[measure])
        return out

    def seq_mean(self, seq, key, measure):
        """The run's mean over its scored frames (J, F: 0-1; kept: a share; ms); NaN when not
        measured or, for ms, when no call was timed."""
        if not self.measured(seq, key):
            return NAN
        return mean(self.per_frame(seq, key, measure).values())

    def overall(self, key, measure):
        """The mean over sequences of the per-sequence means (DAVIS's headline for J and F); for
        ms, the mean over every timed frame of every sequence. NaN when a sequence's run was not
        measured."""
        if not all(self.measured(s, key) for s in self.sequences):
            return NAN
        if measure == "ms":
            values = [v for s in self.sequences for v in self.per_frame(s, key, "ms").values()]
            return mean(values)
        return mean(self.seq_mean(s, key, measure) for s in self.sequences)

    def median_ms(self, key):
        """The median ms over every timed frame of every sequence; NaN as overall()."""
        if not all(self.measured(s, key) for s in self.sequences):
            return NAN
        return median(v for s in self.sequences for v in self.per_frame(s, key, "ms").values())

    def scored_frames(self):
        return sum(len(self.per_frame(s, ("hold", "mask"), "j")) for s in self.sequences)

    def worst_frame(self, seq, key):
        js = self.per_frame(seq, key, "j")
        return min(js, key=lambda i: (js[i], i)) if js else None
# How the report's sentences name a baseline.
READING = {("hold", "mask"): "the held first mask", ("CSRT", "box"): "CSRT (from the box)"}


def machine(load_start):
    """The machine a run measured on, for its meta.json: its CPU, cores and system, and its load
    (the 1-minute average) when the run started (`load_start`, os.getloadavg()) and now: the
    timings share the cores with whatever else ran."""
    return {"cpu": platform.processor() or platform.machine(), "cores": os.cpu_count(),
            "system": platform.platform(),
            "load": [round(load_start[0], 1), round(os.getloadavg()[0], 1)]}
