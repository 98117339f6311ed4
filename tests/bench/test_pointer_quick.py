#!/usr/bin/python3
"""The 3D-mouse benchmark's smoke run, end to end: the scripted sequences and opencv-doc's clips
through the element, every frame reported; the gestures of the short sequence found and none
anywhere else; the report renders its tables and figures without a missing number where the run
measured one.

    test_pointer_quick.py RUN_PY REPORT_PY OUT_DIR
"""
import csv
import json
import os
import shutil
import subprocess
import sys

run, report, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)
subprocess.run(["/usr/bin/python3", run, "--out", out, "--quick"], check=True, timeout=900)

meta = json.load(open(os.path.join(out, "meta.json")))
rows = list(csv.DictReader(open(os.path.join(out, "frames.csv"))))
truth = list(csv.DictReader(open(os.path.join(out, "truth.csv"))))
for s in meta["sequences"]:
    mine = [r for r in rows if r["source"] == "sequence" and r["name"] == s["name"]]
    assert [int(r["frame"]) for r in mine] == list(range(s["frames"])), s["name"]
    assert all(r["status"] for r in mine), f"{s['name']}: a frame without a message"
assert set(meta["clips"]) == {"cup", "box", "vtest", "Megamind"}, meta["clips"]
for name, c in meta["clips"].items():
    mine = [r for r in rows if r["source"] == "clip" and r["name"] == name]
    assert len(mine) == c["frames"] == 40, (name, len(mine), c)
    assert c["width"] > 0 and c["height"] > 0, c
assert sorted(t["kind"] for t in truth) == ["press", "push", "release"], truth

# The gestures: each true one reported within the tolerance, nothing else anywhere.
reported = [(r["name"], r["gesture"], float(r["time"])) for r in rows if r["gesture"]]
for t in truth:
    near = [g for g in reported
            if g[0] == t["name"] and g[1] == t["kind"] and abs(g[2] - float(t["time"])) <= 0.4]
    assert len(near) == 1, (t, reported)
assert len(reported) == len(truth), reported

doc = os.path.join(out, "pointer.md")
subprocess.run(["/usr/bin/python3", report, out, out, doc], check=True, timeout=300)
text = open(doc).read()
assert "| every gesture found within ±0.4 s" in text, text[:2000]
assert "3 of 3 found" in text and "**met**" in text, text[:3000]
assert "nan" not in text.lower(), "a NaN in the document"
for fig in ("depth-gestures.png", "depth-clips.png"):
    assert os.path.getsize(os.path.join(out, "figures", fig)) > 10000, fig
