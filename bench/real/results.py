"""A real-footage run's data, loaded and scored once for the report: the plan (clips and variants),
every run's rows and measures, and which run is which start."""
import csv
import math
import os

import clip_set
from motion import ONE_MOVER
from report_kit import load_meta
from scoring import load_runs, load_truth, run_stats, score
from targets import all_met

VARIANT_ORDER = [""] + clip_set.ALL_VARIANTS


class Results:
    def __init__(self, data_dir):
        self.data_dir = data_dir
        self.meta = load_meta(data_dir)
        self.default = self.meta["default_method"]
        self.runs = load_runs(data_dir)
        self.plan = read_csv(os.path.join(data_dir, "plan.csv"))
        self.motion = {r["clip"]: r for r in read_csv(os.path.join(data_dir, "clips.csv"))}
        self.seeds = {}
        for r in read_csv(os.path.join(data_dir, "seeds.csv")):
            self.seeds.setdefault(r["entry"], []).append(r)
        self.entries = [p["entry"] for p in self.plan]
        self.variant = {p["entry"]: p["variant"] for p in self.plan}
        self.clip_of = {p["entry"]: p["clip"] for p in self.plan}
        self.clips = [c.name for c in clip_set.CLIPS if c.name in self.clip_of.values()]
        self.truth = {e: load_truth(data_dir, e) for e in self.entries}
        self.trackers = {e: [] for e in self.entries}
        for (e, t) in self.runs:
            self.trackers.setdefault(e, []).append(t)
        self.scores = {k: score(rows, self.truth[k[0]]) for k, rows in self.runs.items()
                       if self.truth.get(k[0])}
        self.stats = {k: run_stats(rows) for k, rows in self.runs.items()}
        self.speed = read_csv(os.path.join(data_dir, "speed.csv"))

    def entries_of(self, clip):
        out = [e for e in self.entries if self.clip_of[e] == clip]
        return sorted(out, key=lambda e: VARIANT_ORDER.index(self.variant[e])
                      if self.variant[e] in VARIANT_ORDER else len(VARIANT_ORDER))

    def thrown(self, entry):
        return clip_set.BY_NAME[self.clip_of[entry]].thrown

    def one_mover(self, clip):
        """Whether the no-seed target applies: one object moves (motion.py); None unknown."""
        v = self.motion.get(clip, {}).get("outside_motion", "")
        return None if v == "" else float(v) <= ONE_MOVER

    def start_runs(self, entry, start):
        """The names of the default method's runs of a start on an entry, from its seeds (a
        run missing from the data is still named: it reads "not measured")."""
        seeds = self.seeds.get(entry, [])
        if start == "deepest":
            return [f"projtrack {self.default}"] if seeds else []
        if start == "quarter":
            qs = [s for s in seeds if s["kind"] == "quarter"]
            return [f"projtrack quarter {k} at {s['x']},{s['y']}" for k, s in enumerate(qs, 1)]
        if start == "box":
            return ["projtrack start-box"] if seeds else []
        return ["projtrack no seed"]

    def score_of(self, entry, tracker):
        return self.scores.get((entry, tracker))

    def worst_quarter(self, entry):
        """The quarter start whose run scores worst (kept, then median); None without any."""
        names = self.start_runs(entry, "quarter")
        if not names:
            return None

        def key(n):  # not met first, then the fewest kept, then the largest error
            m = self.score_of(entry, n)
            return (0, -1, 0) if m is None else (self.met(entry, n), m["kept"], -m["median_rel"])
        return min(names, key=key)

    def met(self, entry, tracker):
        m = self.score_of(entry, tracker)
        return m is not None and all_met(m, self.thrown(entry))

    def props(self, entry, tracker):
        return self.meta["clips"].get(entry, {}).get("properties", {}).get(tracker)

    def clip_meta(self, entry):
        return self.meta["clips"].get(entry, {})

    def first_frame(self, clip):
        return int(self.motion.get(clip, {}).get("start", 0) or 0)

    def ms(self, entry, tracker):
        s = self.stats.get((entry, tracker))
        return s["ms"] if s else math.nan


def read_csv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))
