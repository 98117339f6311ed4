#!/usr/bin/python3
"""The DAVIS benchmark's measures (bench/davis/measures.py) on tiny synthetic masks whose answers
are known by hand: J, F (DAVIS's boundary F-measure), kept, and the starts (box, deepest point).

    test_davis_measures.py BENCH_DAVIS_DIR
"""
import math
import sys

import numpy as np

sys.path.insert(0, sys.argv[1])
import dataset  # noqa: E402
import measures as m  # noqa: E402


def square(shape, x, y, side):
    a = np.zeros(shape, bool)
    a[y:y + side, x:x + side] = True
    return a


def close(a, b, tol=1e-9):
    assert abs(a - b) <= tol, (a, b)


shape = (40, 60)
a = square(shape, 10, 10, 10)          # 100 px
b = square(shape, 15, 10, 10)          # overlaps a on 50 px
empty = np.zeros(shape, bool)

# J: intersection over union; both empty is 1, one empty is 0.
close(m.region_j(a, a), 1.0)
close(m.region_j(a, b), 50 / 150)
close(m.region_j(empty, empty), 1.0)
close(m.region_j(a, empty), 0.0)
close(m.region_j(empty, a), 0.0)

# The boundary is DAVIS's seg2bmap: the pixels that differ from their east, south or south-east
# neighbour. For a 10×10 square at (10, 10): its last row and column (inside it), and the row above
# and the column left of it (background whose neighbour is the object), one pixel wide.
bm = m.boundary(a)
expected = np.zeros(shape, bool)
expected[9, 9:20] = True   # above the square (and the corner above-left)
expected[9:20, 9] = True   # left of it
expected[19, 10:20] = True  # its last row
expected[10:20, 19] = True  # its last column
assert (bm == expected).all(), np.argwhere(bm != expected)

# F: identical masks 1; both empty 1; one empty 0; boundaries far apart 0; within the tolerance 1.
close(m.boundary_f(a, a)[0], 1.0)
close(m.boundary_f(empty, empty)[0], 1.0)
close(m.boundary_f(a, empty)[0], 0.0)
close(m.boundary_f(empty, a)[0], 0.0)
far = square(shape, 40, 25, 10)
close(m.boundary_f(a, far, bound_th=2)[0], 0.0)
shifted = square(shape, 11, 10, 10)  # one pixel right: every boundary pixel within 1 px
close(m.boundary_f(a, shifted, bound_th=1)[0], 1.0)
# a 2-pixel shift with a 1-pixel tolerance: the top and bottom rows still match (they overlap
# but for 2 px at each end), the left and right columns do not.
f, p, r = m.boundary_f(a, square(shape, 12, 10, 10), bound_th=1)
assert 0 < f < 1 and abs(p - r) < 1e-9, (f, p, r)
# DAVIS's tolerance: ceil(0.008 × diagonal) px; at 854×480, 8 px: a shift of 8 px matches fully,
# a shift of 9 px does not.
big = (480, 854)
obj = square(big, 300, 200, 100)
close(m.boundary_f(obj, square(big, 308, 200, 100))[0], 1.0)
assert m.boundary_f(obj, square(big, 309, 200, 100))[0] < 1.0

# Centroid and area of a mask; of a box.
c, area = m.centroid_area(a)
close(c[0], 14.5), close(c[1], 14.5), close(area, 100)
assert m.centroid_area(empty) == (None, 0.0)
c, area = m.box_centroid_area((10, 10, 10, 10))
close(c[0], 15), close(c[1], 15), close(area, 100)
assert (m.box_mask((10, 10, 10, 10), shape) == a).all()
assert m.box_mask((-5, -5, 10, 10), shape).sum() == 25  # clipped
assert not m.box_mask(None, shape).any()

# kept: centroid within ¼√(true area) (here 2.5 px for 100 px²) and area within [0.5, 2]×.
tc, ta = (14.5, 14.5), 100.0
assert m.kept((14.5, 14.5), 100, tc, ta)
assert m.kept((17.0, 14.5), 100, tc, ta)          # 2.5 px away: on the limit, kept
assert not m.kept((17.1, 14.5), 100, tc, ta)      # farther
assert m.kept((14.5, 14.5), 50, tc, ta) and m.kept((14.5, 14.5), 200, tc, ta)
assert not m.kept((14.5, 14.5), 49, tc, ta) and not m.kept((14.5, 14.5), 201, tc, ta)
assert not m.kept(None, 0, tc, ta)                # nothing predicted on an object
assert m.kept(None, 0, None, 0)                   # nothing predicted, nothing there: kept
assert not m.kept((3.0, 3.0), 20, None, 0)        # something predicted, nothing there

# The starts: the tight box and the deepest point (maximum of the distance transform).
assert dataset.bbox(a) == (10, 10, 10, 10) and dataset.bbox(empty) is None
rect = np.zeros(shape, bool)
rect[5:16, 20:51] = True  # 31×11: the deepest points lie on its middle row
x, y = dataset.deepest_point(rect)
assert y == 10 and 25 <= x <= 45, (x, y)

# The scored frames: 1 .. N-2.
assert list(m.scored_frames(5)) == [1, 2, 3]
assert not math.isnan(m.region_j(a, b))
print("davis measures: ok")
