"""The report's cost section: projtrack's time with its start counted, against CSRT's in the same
run, and its worst frame against its median frame, per sequence and start, with the targets'
verdicts computed from them (a run not measured is a miss, never a pass)."""
import math

from report_kit import DASH, TARGET, fmt_num, missing

import results as R

STARTS = [("projtrack", "mask"), ("projtrack", "box"), ("projtrack", "click")]
CSRT = ("CSRT", "box")
# The targets: the mean frame (the start included) at most this share of CSRT's over the set, and
# on every sequence; the worst frame at most this many times the median frame.
MEAN_OF_CSRT, SEQUENCE_OF_CSRT, WORST_OVER_MEDIAN = 0.10, 0.15, 3.0


def timed(res, seq, key):
    """The run's times, ms: its start (init) first, then every timed frame; [] if not measured."""
    if not res.measured(seq, key):
        return []
    init = res.runs[(seq,) + key].get("init_ms", "")
    frames = list(res.per_frame(seq, key, "ms").values())
    return ([float(init)] if init != "" else []) + frames


def ratio(a, b):
    return a / b if not missing(a, b) and a and b else math.nan


def of_csrt(res, seqs, key):
    """The mean call of `key` over CSRT's, over every call of the sequences `seqs`."""
    ours = [v for s in seqs for v in timed(res, s, key)]
    theirs = [v for s in seqs for v in timed(res, s, CSRT)]
    return ratio(R.mean(ours), R.mean(theirs)) if ours and theirs else math.nan


def worst_over_median(res, seq, key):
    t = timed(res, seq, key)
    return ratio(max(t), R.median(t)) if t else math.nan


def most(values):
    return max(values) if values and not missing(*values) else math.nan


def verdict(values, limit):
    """met only when every value was measured and is within `limit`."""
    met = values and not missing(*values) and all(v <= limit for v in values)
    return TARGET.holds if met else TARGET.fails


def cost_section(res):
    keys = [k for k in STARTS if k in res.keys]
    lines = ["## Cost, the start counted", "",
             "projtrack's mean time per call with its start (`init`) counted as a frame, over "
             "CSRT's counted the same way in this run (from the box), and projtrack's slowest call "
             "(the start included) over its median call, per sequence and start:", ""]
    head = ["sequence"] + [f"{k[1]}: of CSRT" for k in keys] + [f"{k[1]}: worst / median"
                                                                  for k in keys]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for s in res.sequences:
        cells = [fmt_num(of_csrt(res, [s], k), 2) for k in keys]
        cells += [fmt_num(worst_over_median(res, s, k), 1) for k in keys]
        lines.append(f"| {s} | " + " | ".join(cells) + " |")
    cells = [fmt_num(of_csrt(res, res.sequences, k), 2) for k in keys] + [DASH for _ in keys]
    lines.append("| **all frames** | " + " | ".join(f"**{c}**" for c in cells) + " |")
    overall = [of_csrt(res, res.sequences, k) for k in keys]
    per_seq = [of_csrt(res, [s], k) for s in res.sequences for k in keys]
    worst = [worst_over_median(res, s, k) for s in res.sequences for k in keys]
    lines += ["", "| target | measured | verdict |", "|---|---|---|",
              f"| the mean call, start counted, ≤ {MEAN_OF_CSRT} of CSRT's over the set, from "
              f"every start | {', '.join(f'{k[1]} {fmt_num(v, 2)}' for k, v in zip(keys, overall))}"
              f" | {verdict(overall, MEAN_OF_CSRT)} |",
              f"| ≤ {SEQUENCE_OF_CSRT} of CSRT's on every sequence and start | the most "
              f"{fmt_num(most(per_seq), 2)} | {verdict(per_seq, SEQUENCE_OF_CSRT)} |",
              f"| the worst call ≤ {WORST_OVER_MEDIAN:g}× the median on every sequence and start "
              f"| the most {fmt_num(most(worst), 1)} | {verdict(worst, WORST_OVER_MEDIAN)} |", ""]
    return lines
