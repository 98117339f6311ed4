#!/usr/bin/python3
"""bench/real/report.py on small fixture data written here: the new scoring (a frame is kept when
the centroid is within ¼√area and the area within [0.5, 2]× the truth's), a frame missing from a
run counts as a miss and the report says so, NaN never passes, frames out of view are not scored,
each target's verdict follows the data, and a missing run reads "not measured".

    test_real_report.py BENCH_REAL_DIR WORK_DIR
"""
import csv
import json
import math
import os
import shutil
import sys

bench_real, work = sys.argv[1:3]
sys.path.insert(0, bench_real)
sys.path.insert(0, os.path.join(bench_real, "..", "common"))
import report  # noqa: E402
import scoring  # noqa: E402
import sections  # noqa: E402
from results import Results  # noqa: E402

N = 40
CX, CY, SIDE = 100.0, 100.0, 40
AREA = SIDE * SIDE
DEFAULT = "gap-tolerant-filling"
D = f"projtrack {DEFAULT}"
Q = "projtrack quarter 1 at 90,90"
B = "projtrack start-box"
NS = "projtrack no seed"
RUN_COLUMNS = ("clip,tracker,group,frame,status,measured,centroid_x,centroid_y,area,x,y,width,"
               "height,has_pose,position_x,position_y,depth,push,acquired,us,work,moving_share,"
               "scene_share,detail").split(",")
TRUTH_COLUMNS = ["frame", "centroid_x", "centroid_y", "area", "x", "y", "width", "height",
                 "inner_x", "inner_y", "luma_mean"]
MET, NOT_MET, MISSING = "**met**", "**not met**", "not measured"
# entry: (clip, variant, motion away from the object)
ENTRIES = {"cup": ("cup", "", 0.1), "cup-edge": ("cup", "edge", 0.1),
           "balle1": ("balle1", "", 0.1), "cube": ("cube", "", 0.6)}


def write_csv(path, columns, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, columns)
        w.writeheader()
        w.writerows(rows)


def truth_rows(out_of_view=()):
    return [dict(frame=i, centroid_x=CX, centroid_y=CY, area=AREA, x=CX - SIDE / 2,
                 y=CY - SIDE / 2, width=SIDE, height=SIDE, inner_x=int(CX), inner_y=int(CY),
                 luma_mean=100) if i not in out_of_view else
            dict(frame=i, centroid_x="", centroid_y="", area=0, x="", y="", width="", height="",
                 inner_x="", inner_y="", luma_mean=100) for i in range(N)]


def row(entry, tracker, group, i, us=1000.0, **over):
    """A frame on which the tracker reports the truth exactly."""
    r = dict(clip=entry, tracker=tracker, group=group, frame=i, status="ok", measured=1,
             centroid_x=CX, centroid_y=CY, area=AREA, x=int(CX - SIDE / 2), y=int(CY - SIDE / 2),
             width=SIDE, height=SIDE, has_pose=1, position_x=0, position_y=0, depth=1, push=0,
             acquired=int(i == 0), us=us, work=10, moving_share=0.5, scene_share=0.5, detail="")
    r.update(over)
    return r


def base_runs():
    runs = []
    for e in ENTRIES:
        for name, group in ((D, "projtrack seeded"), (Q, "projtrack quarter"),
                            (B, "projtrack box"), (NS, "projtrack no seed")):
            runs += [row(e, name, group, i) for i in range(N)]
        runs += [row(e, "cvtracker MOSSE", "box tracker", i, us=3000.0) for i in range(N)]
    runs += [row("vtest", NS, "projtrack no seed", i) for i in range(N)]
    return runs


def render(name, runs=None, speed=None, out_of_view=()):
    """Writes the fixture, runs the report; returns (Results, document text, summary rows)."""
    d = os.path.join(work, name)
    data, doc = os.path.join(d, "data"), os.path.join(d, "doc")
    os.makedirs(os.path.join(data, "truth"))
    os.makedirs(doc)
    write_csv(os.path.join(data, "runs.csv"), RUN_COLUMNS, base_runs() if runs is None else runs)
    write_csv(os.path.join(data, "speed.csv"), ["clip", "resolution", "what", "median_us",
                                                "frames"],
              speed if speed is not None else
              [dict(clip=c, resolution="1920x1080", what=w, median_us=us, frames=N)
               for c in ("cup", "balle1", "cube") for w, us in (("frame copy", 100),
                                                               ("projtrack", 500))])
    plan, seeds, clips = [], [], []
    for e, (clip, variant, motion) in list(ENTRIES.items()) + [("vtest", ("vtest", "", 0.8))]:
        plan.append(dict(entry=e, clip=clip, variant=variant))
        if e != "vtest":
            write_csv(os.path.join(data, "truth", e + ".csv"), TRUTH_COLUMNS,
                      truth_rows(out_of_view))
            seeds += [dict(entry=e, kind="deepest", x=100, y=100, w=0, h=0),
                      dict(entry=e, kind="quarter", x=90, y=90, w=0, h=0),
                      dict(entry=e, kind="box", x=80, y=80, w=40, h=40)]
        if not variant:
            clips.append(dict(clip=clip, start=0, frames=N, edge_side="left",
                              outside_motion=motion))
    write_csv(os.path.join(data, "plan.csv"), ["entry", "clip", "variant"], plan)
    write_csv(os.path.join(data, "seeds.csv"), ["entry", "kind", "x", "y", "w", "h"], seeds)
    write_csv(os.path.join(data, "clips.csv"), ["clip", "start", "frames", "edge_side",
                                                "outside_motion"], clips)
    meta = dict(measured="2001-02-03 04:05 UTC", cpu="cpu", cores=2, opencv="4", gstreamer="G",
                default_method=DEFAULT, variants={"dark": {"luma": 0.5, "chroma": 0.8}},
                clips={e: dict(frames=N, width=640, height=480, variant=ENTRIES[e][1],
                               properties={D: "inner-point-x=100 inner-point-y=100"})
                       for e in ENTRIES})
    meta["clips"]["vtest"] = dict(frames=N, width=768, height=576, variant="", properties={})
    with open(os.path.join(data, "meta.json"), "w") as f:
        json.dump(meta, f)
    res = Results(data)
    path = os.path.join(doc, "real_footage.md")
    report.Document(res, doc, path).write(path)
    return res, open(path).read(), {r[0]: r[3] for r in sections.target_summary(res).rows}


def edit(runs, entry, tracker, frames, **over):
    return [dict(r, **over) if (r["clip"], r["tracker"]) == (entry, tracker) and r["frame"] in
            frames else r for r in runs]


def drop(runs, entry, tracker, frames):
    return [r for r in runs if not ((r["clip"], r["tracker"]) == (entry, tracker) and
                                    r["frame"] in frames)]


shutil.rmtree(work, ignore_errors=True)
KEPT = "clicked at the deepest point: kept (worst run)"
THROWN = "clicked at the deepest point (thrown ball): kept (worst run)"
AREA_T = "clicked at the deepest point: area within ±25 % (worst run)"
NO_SEED = "no seed, clips where one object moves: kept (worst run)"
MOSSE = "speed: MOSSE ÷ projtrack at 640×480 (worst clip)"

res, text, v = render("base")
assert set(v.values()) == {MET}, v
assert "nan" not in text.lower() and "## Runs cut short" in text
assert "None: every run has a row for every frame" in text

# A frame missing from a run counts as a miss, and the report says so: 3 of 40 rows dropped.
res, text, v = render("missing-rows", runs=drop(base_runs(), "cup", D, {37, 38, 39}))
m = res.score_of("cup", D)
assert m["missing"] == 3 and m["kept"] == 37 / 40 and m["kept_old"] == 37 / 40, m
assert v[KEPT] == NOT_MET, v
assert "- cup, projtrack gap-tolerant-filling: 3 of 40 frames missing, counted as misses." in text
# A whole run missing: not measured, never met.
res, text, v = render("missing-run", runs=[r for r in base_runs()
                                           if (r["clip"], r["tracker"]) != ("cup-edge", B)])
assert v["started from the true box: kept (worst run)"] == MISSING, v
assert "- cup-edge, projtrack start-box: not measured (no rows), counted as a miss." in text

# NaN never passes: a NaN centroid or area is a miss under both measures; a NaN time makes the
# speed verdict not measured.
t = truth_rows()[0]
t = {k: float(x) for k, x in t.items()}
for over in (dict(centroid_x=math.nan), dict(area=math.nan)):
    r = dict(row("cup", D, "g", 0), **over)
    assert not scoring.kept(r, t), over
assert not scoring.near(dict(row("cup", D, "g", 0), centroid_y=math.nan), t)
res, text, v = render("nan-time", runs=edit(base_runs(), "cup", "cvtracker MOSSE", set(range(N)),
                                            us=math.nan))
assert v[MOSSE] == MISSING, v

# The area condition flips a kept frame: the centroid exact, the area 2.5× the truth's.
r = dict(row("cup", D, "g", 0), area=AREA * 2.5)
assert scoring.near(r, t) and not scoring.kept(r, t)
assert scoring.kept(dict(r, area=AREA * 1.9), t) and not scoring.kept(dict(r, area=AREA * 0.4), t)
res, text, v = render("area", runs=edit(base_runs(), "cup", D, set(range(5)), area=AREA * 2.5))
m = res.score_of("cup", D)
assert m["kept_old"] == 1 and m["kept"] == 35 / 40, m
assert v[KEPT] == NOT_MET and v[AREA_T] == NOT_MET, v
assert "87.5 %" in text or "88 % / 100 %" in text, text

# Frames out of view are not scored; what a run reports on them is counted apart.
res, text, v = render("out-of-view", out_of_view={0, 1, 2, 3},
                      runs=edit(base_runs(), "cup", D, {0, 1, 2, 3}, centroid_x=CX + 90))
m = res.score_of("cup", D)
assert m["in_view"] == 36 and m["kept"] == 1 and m["out_reported"] == 4, m
assert v[KEPT] == MET, v
assert "| 4 of 4 |" in text

# The thrown ball's goal is lower: 34 of 40 (85 %) meets it there, not on the cup.
off = set(range(6))
res, text, v = render("thrown", runs=edit(base_runs(), "balle1", D, off, centroid_x=CX + 30))
assert v[THROWN] == MET and v[KEPT] == MET, v
res, text, v = render("held", runs=edit(base_runs(), "cup", D, off, centroid_x=CX + 30))
assert v[KEPT] == NOT_MET, v

# The no-seed target covers the clips where one object moves: not the cube.
res, text, v = render("no-seed", runs=edit(base_runs(), "cube", NS, set(range(N)), measured=0,
                                           status="searching"))
assert v[NO_SEED] == MET, v
res, text, v = render("no-seed-cup", runs=edit(base_runs(), "cup-edge", NS, set(range(8)),
                                               measured=0, status="searching"))
assert v[NO_SEED] == NOT_MET, v

# vtest: a static region reported flips its verdict; the speed ratio flips with MOSSE's time.
res, text, v = render("static", runs=edit(base_runs(), "vtest", NS, {7}, moving_share=0.001,
                                          scene_share=0.01))
assert v["vtest, no seed: frames reporting a static region"] == NOT_MET, v
res, text, v = render("slow", runs=edit(base_runs(), "cube", "cvtracker MOSSE", set(range(N)),
                                        us=1500.0))
assert v[MOSSE] == NOT_MET, v

# docs/measured.md's block: every target counted, from the same rows.
block = sections.summary(res)
assert "the element meets" in block and "cube (" in block, block
print("real-footage report: ok")
