#!/usr/bin/python3
"""The DAVIS benchmark's quick run, end to end (bench/davis/run.py --quick, then report.py into
the build folder): projtrack and the held mask on two sequences of davis-dev, 10 frames each
(frames 1..8 scored), with the module's default object model and with the flow model. Fails when
projtrack's J from a start falls more than MARGIN points below the value recorded for that model
in davis_quick_j.json beside this file ("j": the default model, "j_flow": the flow model; how they
were measured: its "how"; a start with no recorded value is printed, not judged).
Skipped (exit 77) when the data folder is missing.

    test_davis_quick.py BENCH_DAVIS_DIR DATA_DIR OUT_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys
import time

bench, data, out = sys.argv[1:4]
if not os.path.isdir(os.path.join(data, "JPEGImages", "480p")):
    print(f"SKIP: no DAVIS data at {os.path.normpath(data)} (the development split, expected "
          "beside the repository as ../shared/davis-dev)")
    sys.exit(77)

MARGIN = 5.0  # J points
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "davis_quick_j.json")) as f:
    recorded = json.load(f)

t0 = time.monotonic()


def j_of_run(model, sub):
    """projtrack's J per start (None: not measured) from a quick run with object model `model`
    (None: the module's default) into OUT_DIR/sub."""
    where = os.path.join(out, sub)
    shutil.rmtree(where, ignore_errors=True)
    os.makedirs(where)
    args = [sys.executable, os.path.join(bench, "run.py"), "--data", data, "--out", where,
            "--quick", "--sequences", ",".join(recorded["sequences"]),
            "--frames", str(recorded["frames"]), "--trackers", "projtrack,hold"]
    subprocess.run(args + (["--model", model] if model else []), check=True, timeout=600)
    subprocess.run([sys.executable, os.path.join(bench, "report.py"), where, where,
                    os.path.join(where, "davis.md")], check=True, timeout=300)
    assert os.path.exists(os.path.join(where, "j_per_sequence.png"))
    # The cost section is written; without CSRT in the run its targets against CSRT are misses,
    # never passes.
    text = open(os.path.join(where, "davis.md")).read()
    cost = text[text.index("## Cost, the start counted"):]
    against_csrt = [ln for ln in cost.splitlines() if ln.startswith("|") and "of CSRT's" in ln]
    assert len(against_csrt) == 2, cost[:1200]
    assert all("not measured" in ln and "**not met**" in ln for ln in against_csrt), against_csrt
    runs = {(r["sequence"], r["tracker"], r["start"]): r
            for r in csv.DictReader(open(os.path.join(where, "runs.csv")))}
    frames = list(csv.DictReader(open(os.path.join(where, "frames.csv"))))
    result = {}
    for start in ("mask", "box", "click"):
        measured = [runs[(s, "projtrack", start)]["measured"] == "1" for s in recorded["sequences"]]
        if not all(measured):
            assert start == "mask", (start, "not measured")  # only the mask start may be refused
            result[start] = None
            continue
        per_seq = []
        for s in recorded["sequences"]:
            js = [float(r["j"]) for r in frames
                  if (r["sequence"], r["tracker"], r["start"]) == (s, "projtrack", start)]
            assert len(js) == recorded["frames"] - 2, (s, start, len(js))
            per_seq.append(100 * sum(js) / len(js))
        result[start] = sum(per_seq) / len(per_seq)
    return result


failures = []
for model, key in ((None, "j"), ("flow", "j_flow")):
    name = model or "the default model"
    got = j_of_run(model, model or "default")
    for start, old in recorded[key].items():
        j = got[start]
        if j is None:
            print(f"{name}, from the {start}: not measured")
            continue
        if old is None:
            print(f"{name}, from the {start}: J {j:.1f} (none recorded yet: record it in "
                  "davis_quick_j.json)")
            continue
        print(f"{name}, from the {start}: J {j:.1f}, recorded {old:.1f}, threshold "
              f"{old - MARGIN:.1f}")
        if not j >= old - MARGIN:
            failures.append(f"{name}, {start}: J {j:.1f} < {old:.1f} - {MARGIN:g}")
assert not failures, "J regressed on the quick DAVIS run: " + "; ".join(failures)
print(f"davis quick: ok ({time.monotonic() - t0:.0f} s)")
