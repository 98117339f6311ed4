"""Issue 25's targets, judged on a run's measurements: per clip × variant × start, and the summary.
Goals are requirements, not results; their texts are rendered from these constants."""
import math

from report_kit import MISSING, TARGET, fmt_pct, fmt_x, missing, verdict

GOAL_KEPT = 0.95         # a start's share of in-view frames kept (centroid and area), at least
GOAL_KEPT_THROWN = 0.80  # the same on a thrown ball's clip
GOAL_MEDIAN = 0.05       # median centroid error as a share of √area, at most
GOAL_AREA = 0.90         # share of in-view frames with the area within ±25 %, at least
GOAL_NO_SEED = 0.90      # no seed, on clips where one object moves: kept, at least
GOAL_STATIC = 0          # vtest, no seed: frames reporting a static region
GOAL_MOSSE = 2           # MOSSE's time ÷ projtrack's at 640×480, at least
GOAL_COPIES = 10         # projtrack's time ÷ a frame copy's at 1080p, at most
GOAL_OVER_BUDGET = 0     # frames of any projtrack run that ran out of max-work

STARTS = ["deepest", "quarter", "box"]
START_TEXT = {"deepest": "clicked at the deepest point", "quarter": "clicked at a quarter point",
              "box": "started from the true box", "none": "no seed"}


def start_of(group):
    return {"projtrack seeded": "deepest", "projtrack quarter": "quarter",
            "projtrack box": "box", "projtrack no seed": "none"}.get(group)


def kept_goal(thrown):
    return GOAL_KEPT_THROWN if thrown else GOAL_KEPT


def run_verdicts(m, thrown):
    """(kept, median, area) verdicts of one seeded run's measures m (scoring.score)."""
    if m is None:
        return MISSING, MISSING, MISSING
    return (verdict([m["kept"]], lambda v: v >= kept_goal(thrown), words=TARGET),
            verdict([m["median_rel"]], lambda v: v <= GOAL_MEDIAN, words=TARGET),
            verdict([m["area_ok"]], lambda v: v >= GOAL_AREA, words=TARGET))


def all_met(m, thrown):
    return all(v == TARGET.holds for v in run_verdicts(m, thrown))


def worst(values, pick=min):
    """The worst value; NaN (not measured) when there is none or any is missing."""
    if not values or missing(*values):
        return math.nan
    return pick(values)


def fmt_rel(x):
    """A centroid error as a share of √area: '3.1 %', 'lost'."""
    if missing(x):
        return MISSING
    return "lost" if math.isinf(x) else f"{100 * x:.1f} %"


def worst_of(runs):
    """'; the worst: cup-edge' (the entry whose run keeps the fewest frames; one not measured
    first)."""
    if not runs:
        return ""
    entry, _ = min(runs, key=lambda em: -1 if em[1] is None or missing(em[1]["kept"])
                   else em[1]["kept"])
    return f"; the worst: {entry}"


class Summary:
    """The rows of the summary table: (target, goal, measured text, verdict, met count)."""

    def __init__(self):
        self.rows = []

    def add(self, what, goal, value, holds, fmt, count=""):
        v = verdict([value], holds, words=TARGET)
        shown = MISSING if missing(value) else fmt(value)
        self.rows.append((what, goal, shown, v, count))

    def seeded(self, runs, start, thrown):
        """runs: [(entry, m)] of one start over every entry (m None: not measured)."""
        goal = kept_goal(thrown)
        ms = [m for _, m in runs]
        met = sum(1 for m in ms if m and all_met(m, thrown))
        count = f"{met} of {len(ms)} runs meet all three" + worst_of(runs)
        label = START_TEXT[start] + (" (thrown ball)" if thrown else "")
        kept = worst([m["kept"] if m else math.nan for m in ms])
        self.add(f"{label}: kept (worst run)", f"≥ {fmt_pct(goal)}", kept,
                 lambda v: v >= goal, fmt_pct, count)
        med = worst([m["median_rel"] if m else math.nan for m in ms], max)
        self.add(f"{label}: median centroid error (worst run)",
                 f"≤ {fmt_pct(GOAL_MEDIAN)} of √area", med, lambda v: v <= GOAL_MEDIAN, fmt_rel)
        area = worst([m["area_ok"] if m else math.nan for m in ms])
        self.add(f"{label}: area within ±25 % (worst run)", f"≥ {fmt_pct(GOAL_AREA)}", area,
                 lambda v: v >= GOAL_AREA, fmt_pct)

    def no_seed(self, runs):
        ms = [m for _, m in runs]
        kept = worst([m["kept"] if m else math.nan for m in ms])
        met = sum(1 for m in ms if m and not missing(m["kept"]) and m["kept"] >= GOAL_NO_SEED)
        self.add("no seed, clips where one object moves: kept (worst run)",
                 f"≥ {fmt_pct(GOAL_NO_SEED)}", kept, lambda v: v >= GOAL_NO_SEED, fmt_pct,
                 f"{met} of {len(ms)} runs" + worst_of(runs))

    def speed(self, static, mosse, copies, over_budget):
        self.add("vtest, no seed: frames reporting a static region", f"{GOAL_STATIC}", static,
                 lambda v: v <= GOAL_STATIC, lambda v: f"{v:.0f}")
        self.add("speed: MOSSE ÷ projtrack at 640×480 (worst clip)", f"≥ {GOAL_MOSSE}×", mosse,
                 lambda v: v >= GOAL_MOSSE, fmt_x)
        self.add("speed: projtrack ÷ frame copy at 1920×1080 (worst clip)", f"≤ {GOAL_COPIES}×",
                 copies, lambda v: v <= GOAL_COPIES, fmt_x)
        self.add("frames of any projtrack run over `max-work`", f"{GOAL_OVER_BUDGET}",
                 over_budget, lambda v: v <= GOAL_OVER_BUDGET, lambda v: f"{v:.0f}")
