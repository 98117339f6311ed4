"""The sections of docs/real_footage.md and docs/measured.md's summary, each a function of the run's
Results (results.py) writing into a document (report.Document: .w(line), .res)."""
import math

import clip_set
from motion import ONE_MOVER
from report_kit import DASH, MISSING, TARGET, fmt_num, fmt_pct, fmt_res, fmt_x, missing
from scoring import AREA_MAX, AREA_MIN, WITHIN
from targets import (GOAL_AREA, GOAL_KEPT, GOAL_KEPT_THROWN, GOAL_MEDIAN, START_TEXT, STARTS,
                     Summary, fmt_rel, kept_goal, worst)

PEERS = ["cvtracker MOSSE", "cvtracker KCF", "cvtracker CSRT", "cvtracker MedianFlow", "CamShift"]


def ranges(frames, most=3):
    """'12–40, 50 and 3 shorter stretches' for sorted frame numbers."""
    if not frames:
        return "none"
    runs = []
    for f in frames:
        if runs and f == runs[-1][1] + 1:
            runs[-1][1] = f
        else:
            runs.append([f, f])
    longest = sorted(runs, key=lambda r: (-(r[1] - r[0]), r[0]))[:most]
    text = ", ".join(f"{a}–{b}" if b > a else f"{a}" for a, b in sorted(longest))
    if len(runs) > most:
        text += f" and {len(runs) - most} shorter stretch" + ("es" if len(runs) - most > 1 else "")
    return text


def run_line(m):
    """One run's measures in a sentence."""
    if m is None:
        return f"{MISSING}."
    med = m["median_rel"]
    med = ("lost (no measurement on half the frames or more)" if med == math.inf else
           f"{fmt_rel(med)} of √area")
    text = (f"kept on {fmt_pct(m['kept'])} of {m['in_view']} in-view frames (centroid only: "
            f"{fmt_pct(m['kept_old'])}), median centroid error {med}, area within ±25 % on "
            f"{fmt_pct(m['area_ok'])}")
    if m["missing"]:
        text += f"; {m['missing']} frames missing from the run, counted as misses"
    return text + "."


def cell(res, entry, tracker, judged):
    """'kept % / old %' and, for a judged start, its verdict; a box tracker not run on the
    variant by design: a dash."""
    m = res.score_of(entry, tracker) if tracker else None
    if m is None:
        return DASH if not judged and tracker in PEERS else MISSING
    text = f"{fmt_pct(m['kept'])} / {fmt_pct(m['kept_old'])}"
    if judged:
        text += " met" if res.met(entry, tracker) else " **not met**"
    return text


def header(doc):
    res, w = doc.res, doc.w
    meta = res.meta
    w(f"Measured {meta['measured']} on {meta['cpu']} ({meta['cores']} cores), OpenCV "
      f"{meta['opencv']}, {meta['gstreamer']}; the element's default method "
      f"`{res.default}`.")
    w()
    w("| clip | package | what | frames (from the first in view) | size | in view | variants | "
      "no-seed target |")
    w("|---|---|---|---|---|---|---|---|")
    for clip in res.clips:
        c = clip_set.BY_NAME[clip]
        cm = res.clip_meta(clip)
        t = res.truth.get(clip) or []
        size = fmt_res(f"{cm['width']}x{cm['height']}") if "width" in cm else MISSING
        variants = ", ".join(res.variant[e] for e in res.entries_of(clip) if res.variant[e])
        mover = res.one_mover(clip)
        share = res.motion.get(clip, {}).get("outside_motion", "")
        target = MISSING if mover is None else ("applies" if mover else "does not apply")
        if share:
            target += f" ({100 * float(share):.0f} % of the motion away from the object)"
        first = res.first_frame(clip)
        w(f"| {clip} | {c.package} | {c.what} | {len(t) or cm.get('frames', MISSING)}"
          + (f" (from frame {first})" if first else "") + f" | {size} | "
          f"{sum(1 for r in t if r['area'])} | {variants or 'none'} | {target} |")
    w()
    w("The truth of each clip is bench/real/truth/ (made by colour, shape and motion rules checked "
      "by eye, never from projtrack: bench/real/truth/README.md); a variant's truth is the "
      "clip's silhouettes moved as the variant moves the frame (prepare.py). **Kept**: the "
      f"centroid within {WITHIN:g}·√area of the true one and the area within "
      f"[{AREA_MIN:g}, {AREA_MAX:g}]× the truth's; kept by the centroid alone "
      "beside it (`kept / centroid only` in the tables). Only frames where the object is in view "
      "are scored; a "
      "frame the run has no row for, lost or searching counts as a miss. The no-seed target "
      "applies where one object moves: where at most "
      f"{100 * ONE_MOVER:.0f} % of the pixels that change between frames lie away from the "
      "object (outside its true box grown by half its size; motion.py). The variants: edge — "
      "the frame cropped on the first frame so that the nearest frame edge cuts "
      f"{fmt_pct(clip_set.EDGE_CUT)} of the object's box off; half — half size; mirror; "
      + "; ".join(variant_text(k, v) for k, v in res.meta.get("variants", {}).items()
                  if k not in ("edge", "half", "mirror")) +
      f". Every variant on clips up to {clip_set.LONG_FRAMES} frames; on longer ones "
      f"{', '.join(clip_set.LONG_VARIANTS)} (the run fits in an hour on two cores). The box "
      "trackers start from the first frame's true box and report a box: their area is the box's, "
      "which the area condition compares with the silhouette's (KCF and CSRT run on the clips as "
      "decoded and their edge variants only: 20–250 ms a frame).")
    w()


def variant_text(name, v):
    texts = {"dark": lambda: f"dark — luma at {v['luma']:g}, chroma at {v['chroma']:g}",
             "dim": lambda: f"dim — the light at {v['light']:g}",
             "bright": lambda: f"bright — luma × {v['gain']:g} {v['offset']:+g}",
             "gamma": lambda: f"gamma — luma through a gamma of {v['gamma']:g}",
             "warm": lambda: f"warm — luma × {v['luma']:g}, Cb {v['cb']:+g}, Cr {v['cr']:+g}",
             "noise": lambda: f"noise — σ {v['luma_sigma']:g} on luma, {v['chroma_sigma']:g} "
                              "on chroma",
             "fast": lambda: f"fast — one frame in {v['step']:g}"}
    try:
        return texts[name]()
    except (KeyError, TypeError):
        return f"{name}: settings not recorded"


def target_summary(res):
    s = Summary()
    for thrown in (False, True):
        for start in STARTS:
            runs = []
            for e in res.entries:
                if res.truth.get(e) and res.thrown(e) == thrown:
                    runs += [(e, res.score_of(e, n)) for n in res.start_runs(e, start)]
            if runs:
                s.seeded(runs, start, thrown)
    movers = [(e, res.score_of(e, "projtrack no seed")) for e in res.entries
              if res.truth.get(e) and res.one_mover(res.clip_of[e])]
    s.no_seed(movers)
    vt = res.stats.get(("vtest", "projtrack no seed"))
    mosse = [res.ms(c, "cvtracker MOSSE") / res.ms(c, f"projtrack {res.default}")
             for c in res.clips if res.clip_meta(c).get("width") == 640
             and res.clip_meta(c).get("height") == 480 and res.truth.get(c)]
    copies = []
    for c in res.clips:
        rows = {r["what"]: float(r["median_us"]) for r in res.speed if r["clip"] == c}
        if rows:
            copies.append(rows.get("projtrack", math.nan) / rows.get("frame copy", math.nan))
    budget = sum(st["over_budget"] for (e, t), st in res.stats.items()
                 if t.startswith("projtrack"))
    s.speed(float(vt["static"]) if vt else math.nan, worst(mosse), worst(copies, max),
            float(budget) if res.stats else math.nan)
    return s


def targets(doc):
    w = doc.w
    s = target_summary(doc.res)
    w("## Targets")
    w()
    w(f"Per run of the default method: kept ≥ {fmt_pct(GOAL_KEPT)} (≥ "
      f"{fmt_pct(GOAL_KEPT_THROWN)} of the in-view frames on the thrown ball, balle1), median "
      "centroid error and area as below; every clip and every variant.")
    w()
    w("| target | goal | measured | verdict | runs |")
    w("|---|---|---|---|---|")
    for what, goal, shown, v, count in s.rows:
        w(f"| {what} | {goal} | {shown} | {v} | {count} |")
    w()
    doc.summary_rows = s.rows


def clip(doc, name):
    res, w = doc.res, doc.w
    w(f"## {name}")
    w()
    entries = res.entries_of(name)
    if not res.truth.get(name):
        w(f"No truth in this run: the element runs without a seed only "
          f"({run_stat_line(res, name, 'projtrack no seed')}).")
        w()
        return
    peers = [p for p in PEERS if any((e, p) in res.runs for e in entries)]
    w("| variant | deepest point | quarter points (worst) | start-box | no seed | "
      + " | ".join(p.replace("cvtracker ", "") for p in peers) + " |")
    w("|---|---|---|---|---|" + "---|" * len(peers))
    for e in entries:
        q = res.start_runs(e, "quarter")
        qmet = sum(res.met(e, n) for n in q)
        wq = res.worst_quarter(e)
        deep, box = res.start_runs(e, "deepest"), res.start_runs(e, "box")
        w(f"| {res.variant[e] or 'as decoded'} | {cell(res, e, deep[0] if deep else None, True)} | "
          f"{cell(res, e, wq, True)} ({qmet} of {len(q)} met) | "
          f"{cell(res, e, box[0] if box else None, True)} | "
          f"{cell(res, e, 'projtrack no seed', False)} | "
          + " | ".join(cell(res, e, p, False) for p in peers) + " |")
    w()
    w("Each cell: kept (centroid and area) / kept (centroid only), over the in-view frames; met or "
      "not met: all three targets of the start. The clip as decoded, every run:")
    w()
    w("| run | kept | centroid only | median error (√area) | area ±25 % | missing rows | "
      "reports when out of view | tracked / lost / searching | ms a frame |")
    w("|---|---|---|---|---|---|---|---|---|")
    for t in res.trackers.get(name, []):
        m, st = res.score_of(name, t), res.stats[(name, t)]
        out = f"{m['out_reported']} of {m['out_of_view']}" if m["out_of_view"] else "–"
        w(f"| {t} | {fmt_pct(m['kept'])} | {fmt_pct(m['kept_old'])} | {fmt_rel(m['median_rel'])}"
          f" | {fmt_pct(m['area_ok'])} | {m['missing']} | {out} | {st['tracked']} / {st['lost']}"
          f" / {st['searching']} | {fmt_num(st['ms'], 2)} |")
    w()


def run_stat_line(res, entry, tracker):
    st = res.stats.get((entry, tracker))
    if not st:
        return MISSING
    return (f"{st['tracked']} frames tracked, {st['lost']} lost, {st['searching']} searching, "
            f"{st['static']} reporting a static region")


def static(doc):
    res, w = doc.res, doc.w
    w("## No seed: is a static region ever taken for the object?")
    w()
    w("| clip | frames reporting an object | of them unchanged over two frames | of those, the "
      "scene's background |")
    w("|---|---|---|---|")
    for c in res.clips:
        st = res.stats.get((c, "projtrack no seed"))
        if st:
            w(f"| {c} | {st['tracked']} | {st['still']} | {st['static']} |")
    w()


def speed(doc):
    res, w = doc.res, doc.w
    w("## Speed")
    w()
    w("Medians per frame, every tracker run frame by frame in turn in one process; the clips "
      "scaled to 1920×1080 beside a copy of the frame.")
    w()
    w("| clip | size | projtrack ms | MOSSE ms | MOSSE ÷ projtrack | 1080p: copy µs | projtrack µs "
      "| ÷ copy |")
    w("|---|---|---|---|---|---|---|---|")
    for c in res.clips:
        if not res.truth.get(c):
            continue
        cm = res.clip_meta(c)
        a, b = res.ms(c, f"projtrack {res.default}"), res.ms(c, "cvtracker MOSSE")
        rows = {r["what"]: float(r["median_us"]) for r in res.speed if r["clip"] == c}
        copy, ours = rows.get("frame copy", math.nan), rows.get("projtrack", math.nan)
        mosse = b / a if not missing(a, b) and a else math.nan
        big = ours / copy if not missing(copy, ours) and copy else math.nan
        w(f"| {c} | {cm.get('width')}×{cm.get('height')} | {fmt_num(a, 2)} | {fmt_num(b, 2)} | "
          f"{fmt_x(mosse)} | {fmt_num(copy)} | {fmt_num(ours)} | {fmt_x(big)} |")
    w()
    over = [(k, st["over_budget"]) for k, st in res.stats.items() if st["over_budget"]]
    w("Frames that ran out of `max-work` (status over-budget): " +
      (", ".join(f"{e} {t}: {n}" for (e, t), n in over) if over else "none") + ".")
    w()


def cut_short(doc):
    res, w = doc.res, doc.w
    short = [(k, m["missing"], m["frames"]) for k, m in res.scores.items() if m["missing"]]
    absent = [(e, n) for e in res.entries if res.truth.get(e) for s in STARTS + ["none"]
              for n in res.start_runs(e, s) if (e, n) not in res.runs]
    w("## Runs cut short")
    w()
    if not short and not absent:
        w("None: every run has a row for every frame of its clip.")
    for (e, t), n, total in short:
        w(f"- {e}, {t}: {n} of {total} frames missing, counted as misses.")
    for e, t in absent:
        w(f"- {e}, {t}: not measured (no rows), counted as a miss.")
    w()


def seeded_kept(res, entry):
    """The kept share of every run started from a point or the box on an entry (None: missing)."""
    names = [n for start in ("deepest", "quarter", "box") for n in res.start_runs(entry, start)]
    scores = [res.score_of(entry, n) for n in names]
    return [m["kept"] if m else None for m in scores]


def plain_words(res):
    """Per clip, computed: kept from every start on every variant, on the clip as decoded only,
    from some starts, or from none."""
    groups = {"every": [], "decoded": [], "some": [], "none": []}
    for c in res.clips:
        goal = kept_goal(clip_set.BY_NAME[c].thrown)
        base = seeded_kept(res, c)
        if not base or None in base:
            groups["none"].append(f"{c} (not measured)")
            continue
        entries = res.entries_of(c)
        every = all(k is not None and k >= goal for e in entries for k in seeded_kept(res, e))
        if every:
            groups["every"].append(c)
        elif min(base) >= goal:
            worst = min((e for e in entries if res.variant[e]),
                        key=lambda e: min((k or 0) for k in seeded_kept(res, e)))
            groups["decoded"].append(f"{c} (the worst variant: {res.variant[worst]})")
        elif max(base) >= goal:
            groups["some"].append(f"{c} ({sum(k >= goal for k in base)} of {len(base)} starts)")
        else:
            groups["none"].append(f"{c} (the best start keeps {fmt_pct(max(base))})")
    text = {"every": "kept from every start, on the clip and every variant",
            "decoded": "kept from every start on the clip as decoded, not on every variant",
            "some": "kept from some starts on the clip as decoded",
            "none": "kept from no start"}
    return [f"- {text[g]}: {', '.join(cs) if cs else 'none'}" for g, cs in groups.items()]


def summary(res, link="real_footage.md"):
    """The summary block of docs/measured.md (`link`: the path of docs/real_footage.md from
    there): per start how many runs meet the targets and the worst, the other verdicts, and per
    clip what works."""
    s = target_summary(res)
    met = sum(r[3] == TARGET.holds for r in s.rows)
    out = [f"On the real-footage development set ({len(res.clips)} clips from Debian's "
           "opencv-doc, python3-mecavideo and visp-images-data, each with its variants; "
           f"[real_footage.md]({link})), the element meets {met} of the "
           f"{len(s.rows)} targets set for it there. A run clicked on the object or started from its box meets "
           f"its own when it keeps ≥ {fmt_pct(GOAL_KEPT)} of the frames in which the object is "
           f"in view (≥ {fmt_pct(GOAL_KEPT_THROWN)} on the thrown ball), its median centroid "
           f"error is ≤ {fmt_pct(GOAL_MEDIAN)} of √area and its area within ±25 % on ≥ "
           f"{fmt_pct(GOAL_AREA)} of them:", ""]
    for what, goal, shown, v, count in s.rows:
        if what.startswith("no seed"):
            out.append(f"- {what}: {shown} (goal {goal}): {v.strip('*')}; {count}")
        elif what.endswith("kept (worst run)") and count:
            runs, _, entry = count.partition("; the worst: ")
            out.append(f"- {what.replace(': kept (worst run)', '')}: {runs}; the worst, "
                       f"{entry}, keeps {shown}")
        elif not count and ("median" in what or "area within" in what):
            continue
        else:
            out.append(f"- {what}: {shown} (goal {goal}): {v.strip('*')}")
    out += ["", "In plain words, from the user's point or box (kept: the share of in-view frames "
            "in which the centroid and the area are right):", ""]
    out += plain_words(res)
    out += ["", "Kept when clicked at the deepest point / from the true box / with "
            "no seed, on the clip as decoded (the range over its variants):", ""]
    for c in res.clips:
        if not res.truth.get(c):
            out.append(f"- {c}: no truth in this run.")
            continue
        parts = []
        for name in (f"projtrack {res.default}", "projtrack start-box", "projtrack no seed"):
            m = res.score_of(c, name)
            ks = [v["kept"] for v in (res.score_of(e, name) for e in res.entries_of(c)
                                      if res.variant[e]) if v]
            rng = f"{100 * min(ks):.0f}–{100 * max(ks):.0f} %" if ks else MISSING
            parts.append(f"{fmt_pct(m['kept']) if m else MISSING} ({rng})")
        out.append(f"- {c} ({clip_set.BY_NAME[c].what}): " + " / ".join(parts))
    return "\n".join(out)
