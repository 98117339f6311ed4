#!/usr/bin/python3
"""The DAVIS benchmark's runners (bench/davis/runners.py) on a stand-in `projtrack` module whose
tracker holds the mask it was started from, so the expected J is known exactly: a mask start is
measured and scored right, and a module that refuses a mask start (as one built before the mask
start did, with a TypeError) leaves that start not measured, never zero. The real module runs in
davis_quick. Also the published table's parser (dataset.published) on a small README.

    test_davis_runners.py BENCH_DAVIS_DIR OUT_DIR
"""
import os
import sys
import types

import numpy as np

sys.path.insert(0, sys.argv[1])
out = sys.argv[2]
import dataset  # noqa: E402
import measures  # noqa: E402
import runners  # noqa: E402


class Result:
    def __init__(self, mask):
        self.mask = mask
        c, a = measures.centroid_area(mask > 0)
        self.centroid, self.area, self.status, self.ok = c, a, "ok", True


class HoldingTracker:
    """Holds whatever it was started with: a mask as given, a box filled, a point as one pixel."""
    takes_mask = True

    def __init__(self, **settings):
        self.settings = dict(model=settings.get("model", "flow"))

    def init(self, frame, where):
        h, w = frame.shape[:2]
        if isinstance(where, np.ndarray):
            if not self.takes_mask:
                raise TypeError("point or box: a number expected, not ndarray")
            assert where.shape == (h, w) and where.dtype == np.uint8, (where.shape, where.dtype)
            self.mask = where.copy()
        elif len(where) == 4:
            self.mask = measures.box_mask(where, (h, w)).astype(np.uint8) * 255
        else:
            self.mask = np.zeros((h, w), np.uint8)
            self.mask[where[1], where[0]] = 255
        return True

    def track(self, frame):
        return Result(self.mask)


stand_in = types.ModuleType("projtrack")
stand_in.Tracker = HoldingTracker
sys.modules["projtrack"] = stand_in

h, w = 48, 64
frames = [np.full((h, w, 3), 100, np.uint8) for _ in range(6)]
truth = np.zeros((h, w), bool)
truth[10:30, 20:36] = True
truth[10:14, 20:24] = False  # not a rectangle: its box is not the mask

# The mask start: the held mask is the truth on every frame: J 1, kept.
gen = runners.runner("projtrack", "mask", frames, truth, 4)
_, init_ms = next(gen)
preds = list(gen)
assert [i for i, _ in preds] == [1, 2, 3, 4]
for i, p in preds:
    assert measures.region_j(p.mask, truth) == 1.0
    assert measures.kept(p.centroid, p.area, *measures.centroid_area(truth))

# The box start is given the tight box: J = the mask's share of its box.
gen = runners.runner("projtrack", "box", frames, truth, 4)
next(gen)
_, p = next(gen)
assert abs(measures.region_j(p.mask, truth) - truth.sum() / (20 * 16)) < 1e-9

# The click is the deepest point, inside the mask.
gen = runners.runner("projtrack", "click", frames, truth, 4)
next(gen)
_, p = next(gen)
ys, xs = np.nonzero(p.mask)
assert truth[ys[0], xs[0]]

# A module that refuses a mask: NotMeasured (the driver records "not measured").
HoldingTracker.takes_mask = False
try:
    runners.runner("projtrack", "mask", frames, truth, 4)
    raise AssertionError("a refused mask start must not be measured")
except runners.NotMeasured as e:
    assert "mask" in str(e)
# ... while a refused box is an error, not a missing measurement.
HoldingTracker.init = lambda self, frame, where: (_ for _ in ()).throw(ValueError("no"))
try:
    runners.runner("projtrack", "box", frames, truth, 4)
    raise AssertionError("a refused box start must raise")
except ValueError:
    pass

# --model reaches the constructor.
assert runners.make_projtrack("edges").settings["model"] == "edges"
assert runners.make_projtrack(None).settings["model"] == "flow"

# The held first mask: the first mask on every frame, no call timed.
gen = runners.runner("hold", "mask", frames, truth, 3)
next(gen)
assert all((p.mask == truth).all() and p.ms != p.ms for _, p in gen)

# The published table of a README like davis-dev's: the rows of sequences, not the frames table
# nor the mean row.
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, "README.md"), "w") as f:
    f.write("| sequence | frames | what |\n|---|---|---|\n| a | 10 | x |\n\n"
            "| sequence | OFL | BVS |\n|---|---|---|\n| a | 52.2 | 50.0 |\n| b | 10.4 | 3.3 |\n"
            "| **mean** | **31.3** | **26.7** |\n")
table, methods = dataset.published(out)
assert methods == ["OFL", "BVS"], methods
assert table == {"OFL": {"a": 52.2, "b": 10.4}, "BVS": {"a": 50.0, "b": 3.3}}, table
assert dataset.published(os.path.join(out, "nowhere")) == ({}, [])
print("davis runners: ok")
