#!/usr/bin/python3
"""The several-objects benchmark's quick run, end to end (bench/multi/run.py --quick, then
report.py into the build folder): one 2×2 mosaic of davis-dev of 8 frames, one crossing of 16 and
the cost run on 6. Checks that the report is written with its sections, its tables and its target
verdicts (met or not met: a target is never left without one, and one whose numbers were not
measured is not met), the contact sheet beside it, and the run's data (every object of every
scene scored on frames 1 .. N-2 by every run that was measured). The numbers themselves are the
full run's business (docs/multi.md). Skipped (exit 77) when the data folder is missing.

    test_multi_quick.py BENCH_MULTI_DIR DATA_DIR OUT_DIR
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

t0 = time.monotonic()
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
subprocess.run([sys.executable, os.path.join(bench, "run.py"), "--data", data, "--out", out,
                "--quick"], check=True, timeout=600)
doc = os.path.join(out, "multi.md")
subprocess.run([sys.executable, os.path.join(bench, "report.py"), out, out, doc], check=True,
               timeout=300)

text = open(doc, encoding="utf-8").read()
sections = ["# Several objects at once", "## Mosaics: together against alone",
            "## Crossings: one object in front of another",
            "## Cost: 1, 2, 4 and 8 objects against as many CSRTs", "## Contact sheet", "## The run"]
at = [text.find(s) for s in sections]
assert all(i >= 0 for i in at), [s for s, i in zip(sections, at) if i < 0]
assert at == sorted(at), "sections out of order"

# every target row has a verdict, met or not met; a row whose numbers read "not measured" is not met
targets, in_table = [], False
for ln in text.splitlines():
    if ln.startswith("| target | measured | verdict |"):
        in_table = True
    elif not ln.startswith("|"):
        in_table = False
    elif in_table and not ln.startswith("|---"):
        targets.append(ln)
assert len(targets) >= 4 + 8 + 4, len(targets)
for ln in targets:
    verdict = ln.rstrip().rsplit("|", 2)[-2].strip()
    assert verdict in ("**met**", "**not met**"), ln
    if "not measured" in ln.rsplit("|", 2)[0]:
        assert verdict == "**not met**", ln

assert os.path.getsize(os.path.join(out, "contact_sheet.png")) > 10000
assert "contact_sheet.png" in text

meta = json.load(open(os.path.join(out, "meta.json")))
assert meta["quick"] and [s["kind"] for s in meta["scenes"]] == ["mosaic", "crossing"], meta["scenes"]
runs = list(csv.DictReader(open(os.path.join(out, "runs.csv"))))
rows = list(csv.DictReader(open(os.path.join(out, "frames.csv"))))
for s in meta["scenes"]:
    for r in runs:
        if r["scene"] != s["name"] or r["measured"] != "1":
            continue
        frames = sorted(int(x["frame"]) for x in rows
                        if (x["scene"], x["run"], x["start"], x["object"]) ==
                        (s["name"], r["run"], r["start"], r["object"]))
        assert frames == list(range(1, s["frames"] - 1)), (s["name"], r["run"], r["start"],
                                                          r["object"], frames)
# the alone and CSRT runs need no MultiTracker: they are measured on every object
for kind in ("alone", "CSRT"):
    assert all(r["measured"] == "1" for r in runs if r["run"] == kind), kind
cost = list(csv.DictReader(open(os.path.join(out, "cost.csv"))))
assert sorted({int(r["objects"]) for r in cost}) == [1, 2, 4, 8]
print(f"multi quick: ok ({time.monotonic() - t0:.0f} s)")
