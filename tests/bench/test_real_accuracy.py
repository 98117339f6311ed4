#!/usr/bin/python3
"""Real-footage accuracy: short segments of clips of the development set run through the element
(projtrack-real, the default method at every start) and scored as ./run bench --real scores them;
fails when a start keeps fewer frames than today's tracker did, less a margin. Raise a threshold
when the tracker gets better (the measured values are printed).

    test_real_accuracy.py PROJTRACK_REAL BENCH_REAL_DIR CLIPS_ROOT OUT_DIR
"""
import os
import shutil
import subprocess
import sys
import time

real, bench_real, root, out = sys.argv[1:5]
if not os.path.isdir(os.path.join(root, "usr")):
    sys.exit(f"{root}: no clips there (./run test fetches python3-mecavideo and visp-images-data)")
sys.path.insert(0, bench_real)
sys.path.insert(0, os.path.join(bench_real, "..", "common"))
from results import Results  # noqa: E402

FRAMES = 40   # a segment: the first FRAMES frames from the first in-view frame
MARGIN = 0.1  # a threshold is the share measured on 2026-11-25 less this (not below 0)
ENTRIES = ["cup", "balle1", "cube", "ellipse-edge"]
# (entry, start): (kept, kept centroid only) measured by today's tracker on the segment.
MEASURED = {
    ("cup", "deepest"): (1.0, 1.0), ("cup", "quarter"): (1.0, 1.0), ("cup", "box"): (1.0, 1.0),
    ("cup", "none"): (0.925, 0.925),
    # The ball is held on every frame of the segment (centroid only); the area condition fails
    # while the first silhouette is its bright core, until the colours along its outline are
    # learned (about half the segment from the deepest point or a box).
    ("balle1", "deepest"): (0.525, 1.0), ("balle1", "quarter"): (0.525, 1.0),
    ("balle1", "box"): (0.525, 1.0), ("balle1", "none"): (0.6, 0.625),
    ("cube", "deepest"): (0.0, 0.0), ("cube", "quarter"): (0.0, 0.0), ("cube", "box"): (0.0, 0.0),
    ("cube", "none"): (0.0, 0.0),
    ("ellipse-edge", "deepest"): (1.0, 1.0), ("ellipse-edge", "quarter"): (1.0, 1.0),
    ("ellipse-edge", "box"): (1.0, 1.0), ("ellipse-edge", "none"): (0.0, 0.0),
}

t0 = time.monotonic()
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
subprocess.run([sys.executable, os.path.join(bench_real, "prepare.py"), root,
                os.path.join(bench_real, "truth"), out, "--frames", str(FRAMES),
                "--entries", ",".join(ENTRIES)], check=True, timeout=300,
               stderr=subprocess.DEVNULL)
subprocess.run([real, "--plan", out, "--out", out, "--only-default"], check=True, timeout=600)
res = Results(out)
assert res.entries == ENTRIES, (res.entries, "the clips are not all found: ./run test fetches them")

failures = []
for (entry, start), (kept, old) in MEASURED.items():
    names = res.start_runs(entry, start)
    assert names, (entry, start)
    for name in names:
        m = res.score_of(entry, name)
        assert m is not None, (entry, name, "not measured")
        assert m["frames"] == FRAMES and m["missing"] == 0, (entry, name, m["frames"])
        print(f"{entry:13s} {name:40s} kept {m['kept']:.3f} (centroid only {m['kept_old']:.3f})"
              f", threshold {max(0, kept - MARGIN):.2f}")
        if not m["kept"] >= max(0.0, kept - MARGIN) or not m["kept_old"] >= max(0.0, old - MARGIN):
            failures.append((entry, name, m["kept"], m["kept_old"], kept, old))
assert not failures, "accuracy regressed: " + "; ".join(
    f"{e} {n}: kept {k:.2f} (was {k0:.2f}), centroid only {o:.2f} (was {o0:.2f})"
    for e, n, k, o, k0, o0 in failures)
print(f"real-footage accuracy: ok ({time.monotonic() - t0:.0f} s)")
