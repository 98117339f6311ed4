"""What the benchmarks' reports (bench/paper, bench/speed, bench/real) share: when a verdict holds,
how a number reads in the documents, and the files every benchmark writes beside its results.
Defined once here so that the three documents cannot drift apart.

A report imports it with its own folder's sibling on the path:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "common"))
    from report_kit import ...
"""
import collections
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")  # the reports draw into files: no display, before pyplot is imported
import matplotlib.pyplot as plt  # noqa: E402  (the reports draw with this one)

__all__ = ["CLAIM", "DASH", "MISSING", "TARGET", "Words", "fmt_num", "fmt_pct", "fmt_pct_g",
           "fmt_res", "fmt_x", "frame_size", "load_meta", "load_methods", "missing", "plt", "span",
           "verdict"]

MISSING = "not measured"  # a number, or a verdict resting on one, that the run did not measure
DASH = "–"                # an empty table cell

# The words of a verdict: a claim of the paper's holds, partly holds or fails (the table bolds
# them); a target is met or not, never in part.
Words = collections.namedtuple("Words", "holds partly fails")
CLAIM = Words("holds", "partly", "fails")
TARGET = Words("**met**", "**not met**", "**not met**")


def missing(*values):
    """True when any of the numbers was not measured: None or NaN."""
    return any(v is None or (isinstance(v, float) and math.isnan(v)) for v in values)


def verdict(values, holds, partly=False, words=CLAIM):
    """The verdict from the numbers it rests on: MISSING when any of them is missing, so missing
    data never passes (nor fails); otherwise words.holds, words.partly or words.fails. `holds` is
    a bool, or a function of the values, called only when none is missing."""
    if missing(*values):
        return MISSING
    if callable(holds):
        holds = holds(*values)
    return words.holds if holds else (words.partly if partly else words.fails)


# ---- numbers as the documents write them --------------------------------------------------------

def fmt_num(x, digits=0, unit="", absent=MISSING):
    """x with `digits` decimals and its unit, or `absent` when it was not measured."""
    return absent if missing(x) else f"{x:.{digits}f}{unit}"


def fmt_x(x, absent=MISSING):
    """A ratio: '2.5×'."""
    return fmt_num(x, 1, "×", absent)


def fmt_pct(x, digits=0, absent=MISSING, finer_under=0.0):
    """A share as a percentage with `digits` decimals, and one more when it lies between 0 and
    `finer_under`; `absent` when it was not measured."""
    if missing(x):
        return absent
    if 0 < x < finer_under:
        digits += 1
    return f"{100 * x:.{digits}f} %"


def fmt_pct_g(x):
    """A share as a percentage with only the digits it has: '2.5 %', '25 %'."""
    return f"{100 * x:g} %"


def span(values, fmt, unit=""):
    """'a–b unit' over the values, formatted ('a unit' when both ends read the same); MISSING when
    there are none or any is missing."""
    if not values or missing(*values):
        return MISSING
    lo, hi = fmt(min(values)), fmt(max(values))
    return (lo if lo == hi else f"{lo}–{hi}") + unit


def frame_size(res):
    """(width, height) of a frame size as the data writes it: '1920x1080'."""
    width, height = res.split("x")
    return int(width), int(height)


def fmt_res(res):
    """A frame size as the data writes it ('1920x1080') as the documents do: 1920×1080."""
    return res.replace("x", "×")


# ---- what every benchmark writes beside its results ---------------------------------------------

def load_methods(results_dir):
    """The library's table of methods as the benchmark wrote it (methods.csv), in the library's
    order: one dict a method with method, family, iterative, from_paper, trace, description."""
    with open(os.path.join(results_dir, "methods.csv")) as f:
        return list(csv.DictReader(f))


def load_meta(results_dir):
    """The run's settings and machine, as the benchmark recorded them (meta.json)."""
    with open(os.path.join(results_dir, "meta.json")) as f:
        return json.load(f)


def replace_between(path, begin, end, block, who):
    """Writes `block` between the marker lines `begin` and `end` of the file at `path` (each
    marker then its own line); exits naming `who` when the file has no such markers. True when the
    file changed."""
    with open(path) as f:
        text = f.read()
    if begin not in text or end not in text:
        raise SystemExit(f"{who}: {path} has no markers {begin} ... {end}")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    new = head + begin + "\n" + block + "\n" + end + tail
    if new != text:
        with open(path, "w") as f:
            f.write(new)
    return new != text
