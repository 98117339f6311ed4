"""What bench/paper/report.py's parts share: the verdicts' thresholds (the claims' words made
numbers), reading the results and the statistics over runs."""
import csv
import gzip
import math
import os
from collections import defaultdict

import numpy as np

from report_kit import DASH, fmt_num, fmt_pct


# The methods and their traits are read from RESULTS_DIR/methods.csv (the library's table of
# methods, written by projtrack-bench); the claims and targets below name the methods they are
# about.
OURS = 'gap-tolerant-filling'  # issue 8's targets are this method's
# What the verdicts count as holding (the claims' words made numbers; none of them is a result).
C1_FACTOR = 2        # C1: ray-casting's spread on the hand is over this many times grid-filling's
EXACT_AREA = 0.03    # C4: "exact": median |area error| under this, and centroid error under
EXACT_CENTROID = 1.0  # this many px
LEAKS = 0.5          # C4: "leaks": more than this share of the runs
NO_MORE = 0.02       # C5: "no more sensitive": a leak rate at most this much above another's
FAR_LESS = 0.5       # C5: "far less": at most this share of pixel-filling's leak rate
G2_WITHIN = 0.01     # G2: area error within this of pixel-filling's
G3_FACTOR = 2        # G3: cost at most this many times grid-filling's
TIE = 0.02           # the sweep: a cheaper value within this share of the best score wins
PEERS = ['opencv-floodfill', 'opencv-components']
NUMERIC = ['width', 'height', 'scale', 'gap_rate', 'acquired_frame', 'correct', 'sane_after',
           'spurious', 'instance', 'seed_x', 'seed_y', 'centroid_x', 'centroid_y', 'area',
           'true_centroid_x', 'true_centroid_y', 'true_area', 'centroid_error_px',
           'centroid_error_rel', 'area_error', 'leak', 'iterations', 'rays_cast', 'pixels_visited',
           'time_us', 'value', 'contour_pixels']


def open_text(path):
    """A results file, plain or gzip-compressed (./run bench compresses the large ones)."""
    if not os.path.exists(path) and os.path.exists(path + '.gz'):
        return gzip.open(path + '.gz', 'rt')
    return open(path)


def load(path):
    rows = []
    with open_text(path) as f:
        for r in csv.DictReader(f):
            for k in NUMERIC:
                if k in r:
                    r[k] = float(r[k]) if r[k] != '' else math.nan
            rows.append(r)
    return rows


def select(rows, **kw):
    return [r for r in rows if all(r[k] == v for k, v in kw.items())]


def med(values):
    v = [x for x in values if not math.isnan(x)]
    return float(np.median(v)) if v else math.nan


def mean(values):
    v = [x for x in values if not math.isnan(x)]
    return float(np.mean(v)) if v else math.nan


# This document's numbers: one decimal unless told, a dash in a cell not measured.
def pct(x, digits=1):
    return fmt_pct(x, digits, DASH)


def num(x, digits=1):
    return fmt_num(x, digits, absent=DASH)


def leak_rate(rows):
    return mean([r['leak'] for r in rows]) if rows else math.nan


def abs_area_error(rows):
    return med([abs(r['area_error']) for r in rows])


def spread(rows):
    """Instability across inner points: per scene, the RMS distance of the centroids from their
    mean, relative to sqrt(true area); averaged over scenes."""
    by_scene = defaultdict(list)
    for r in rows:
        if not math.isnan(r['centroid_x']):
            by_scene[(r['resolution'], r['object'], r['gap_rate'], r['spurious'],
                      r['instance'])].append(r)
    values = []
    for rs in by_scene.values():
        xs = np.array([r['centroid_x'] for r in rs])
        ys = np.array([r['centroid_y'] for r in rs])
        rms = math.sqrt(np.mean((xs - xs.mean()) ** 2 + (ys - ys.mean()) ** 2))
        values.append(rms / math.sqrt(rs[0]['true_area']))
    return mean(values)


def area_spread(rows):
    """Instability of the area across inner points: per scene, the standard deviation of
    area / true area; averaged over scenes."""
    by_scene = defaultdict(list)
    for r in rows:
        if not math.isnan(r['area']):
            by_scene[(r['resolution'], r['object'], r['gap_rate'], r['spurious'],
                      r['instance'])].append(r['area'] / r['true_area'])
    return mean([float(np.std(v)) for v in by_scene.values()])


def score(rows):
    """One error number for choosing parameters (lower is better): the mean |area error| plus the
    mean centroid error / sqrt(area), each capped at 1 per run so that a leak counts as one bad
    run however far it spread, and a run without features counts as 1 + 1."""
    area = [min(abs(r['area_error']), 1.0) if not math.isnan(r['area_error']) else 1.0
            for r in rows]
    cen = [min(r['centroid_error_rel'], 1.0) if not math.isnan(r['centroid_error_rel']) else 1.0
           for r in rows]
    return float(np.mean(area) + np.mean(cen)) if rows else math.nan
