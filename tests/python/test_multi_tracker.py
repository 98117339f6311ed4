#!/usr/bin/python3
"""projtrack.MultiTracker on generated numpy frames: two ellipses moving over a textured background,
each followed with its own id; bad input raising ValueError or TypeError with a clear message; ids
never reused; update()'s shapes as OpenCV's legacy MultiTracker's; one object giving what a Tracker
gives on the same frames; and docs/python.md's two-object loop, run as written on opencv-doc's
vtest.avi (skipped without it). Run with PYTHONPATH=<build>/python."""
import os
import re
import unittest
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import projtrack

W, H = 320, 240
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
VTEST = '/usr/share/doc/opencv-doc/examples/data/vtest.avi'


def ellipse(cx, cy, ax, ay):
    """The ellipse's pixels: a bool (H, W) mask."""
    yy, xx = np.mgrid[0:H, 0:W]
    return ((xx - cx) / ax) ** 2 + ((yy - cy) / ay) ** 2 <= 1


# The two objects on frame i: a red ellipse going right, a blue one going left and down; they never
# meet (an object in front of another is the library's test, tests/tracker).
def red(i):
    return 80 + 3 * i, 100, 30, 20


def blue(i):
    return 230 - 3 * i, 150 + i, 25, 35


BACKGROUND = np.random.default_rng(7).integers(90, 150, (H, W, 3), dtype=np.uint8)


def frame(i):
    """Both ellipses on a textured grey background (BGR)."""
    f = BACKGROUND.copy()
    f[ellipse(*red(i))] = (30, 30, 200)
    f[ellipse(*blue(i))] = (200, 60, 20)
    return f


def box_of(cx, cy, ax, ay):
    return (cx - ax, cy - ay, 2 * ax, 2 * ay)


def summary(r):
    return (r.status, r.centroid, r.area, r.box, r.inner_point, r.acquired,
            None if r.pose is None else tuple(r.pose))


class TwoObjects(unittest.TestCase):
    def test_each_followed_with_its_id(self):
        tracker = projtrack.MultiTracker()
        a = tracker.add(frame(0), box=box_of(*red(0)))
        b = tracker.add(frame(0), point=blue(0)[:2])
        self.assertEqual((a, b), (1, 2))
        self.assertEqual(tracker.ids, [a, b])
        self.assertEqual(len(tracker), 2)
        self.assertIn(a, tracker)
        self.assertNotIn(3, tracker)
        for i in range(15):
            results = tracker.track(frame(i))
            self.assertEqual(list(results), [a, b])  # in the order of ids
            for id, where in ((a, red(i)), (b, blue(i))):
                r = results[id]
                self.assertEqual(r.id, id)
                self.assertTrue(r.ok, f'frame {i}, object {id}: {r}')
                self.assertLess(np.hypot(r.centroid[0] - where[0], r.centroid[1] - where[1]), 3,
                                f'frame {i}, object {id}: {r}')
                truth = ellipse(*where)
                self.assertAlmostEqual(r.area / truth.sum(), 1, delta=0.15, msg=f'frame {i}')
                # Its mask is its own ellipse, not the other's.
                on = r.mask > 0
                self.assertGreater((on & truth).sum() / truth.sum(), 0.9, f'frame {i}')
                self.assertGreater((on & truth).sum() / on.sum(), 0.9, f'frame {i}')
                np.testing.assert_array_equal(tracker.mask(id), r.mask)
        self.assertEqual(tracker.frames, 15)
        self.assertIn(' id=1 ', repr(results[a]))

    def test_mask_starts_of_any_dtype(self):
        for dtype in (bool, np.uint8, np.int64, np.float32, np.float16):
            with self.subTest(dtype=np.dtype(dtype).name):
                tracker = projtrack.MultiTracker()
                a = tracker.add(frame(0), mask=ellipse(*red(0)).astype(dtype))
                b = tracker.add(frame(0), ellipse(*blue(0)).astype(dtype) * 3)  # `where`
                results = tracker.track(frame(0))
                self.assertTrue(results[a].ok and results[b].ok, results)
                self.assertLess(abs(results[a].centroid[0] - red(0)[0]), 3)
                self.assertLess(abs(results[b].centroid[0] - blue(0)[0]), 3)

    def test_track_without_masks_and_with_time(self):
        tracker = projtrack.MultiTracker(fps=10)
        a = tracker.add(frame(0), point=red(0)[:2])
        r = tracker.track(frame(0), mask=False, t=0.5)[a]
        self.assertTrue(r.ok)
        self.assertIsNone(r.mask)
        self.assertEqual(tracker.mask(a).shape, (H, W))

    def test_tracker_results_have_id_0(self):
        tracker = projtrack.Tracker()
        self.assertEqual(tracker.track(frame(0), point=red(0)[:2]).id, 0)
        self.assertNotIn(' id=', repr(tracker.track(frame(1))))


class Frames(unittest.TestCase):
    """Frames of another size or kind, taken as Tracker takes them, for every object; a start in
    them is in their pixels."""

    def test_new_size_and_kind(self):
        tracker = projtrack.MultiTracker()
        a = tracker.add(frame(0), point=red(0)[:2])
        b = tracker.add(frame(0), point=blue(0)[:2])
        for i in range(4):
            tracker.track(frame(i))
        small = frame(4)[::2, ::2].copy()  # half the size: the objects follow, scaled
        results = tracker.track(small)
        for id, where in ((a, red(4)), (b, blue(4))):
            self.assertTrue(results[id].ok, results[id])
            self.assertLess(abs(results[id].centroid[0] - where[0] / 2), 3, results[id])
            self.assertEqual(results[id].mask.shape, (H // 2, W // 2))
        gray = np.ascontiguousarray(frame(5)[..., 2])  # another kind: the colours relearned
        self.assertEqual(list(tracker.track(gray)), [a, b])
        # A start on a frame of the first size: the objects are scaled back before it is checked.
        with self.assertRaisesRegex(ValueError, 'add: object 1 is there already'):
            tracker.add(frame(6), point=red(6)[:2])
        self.assertEqual(tracker.mask(a).shape, (H, W))

    def test_threads_share_one_tracker(self):
        tracker = projtrack.MultiTracker()
        tracker.add(frame(0), point=red(0)[:2])
        tracker.add(frame(0), point=blue(0)[:2])

        def work():
            for i in range(4):
                tracker.track(frame(i))
                self.assertEqual(tracker.ids, [1, 2])
        with ThreadPoolExecutor(3) as pool:
            for done in [pool.submit(work) for _ in range(3)]:
                done.result()  # a thread's error raised here
        self.assertEqual(tracker.frames, 12)


class SameAsTracker(unittest.TestCase):
    """One object through a MultiTracker is the Tracker's: the same results and masks, frame by
    frame, from a point, a box and a mask (the start given with the frame it starts on)."""

    def test_one_object(self):
        starts = {'point': red(0)[:2], 'box': box_of(*red(0)), 'mask': ellipse(*red(0))}
        for kind, where in starts.items():
            with self.subTest(start=kind):
                single, multi = projtrack.Tracker(), projtrack.MultiTracker()
                id = multi.add(frame(0), **{kind: where})
                for i in range(12):
                    one = single.track(frame(i), **({kind: where} if i == 0 else {}))
                    many = multi.track(frame(i))
                    self.assertEqual(list(many), [id])
                    self.assertEqual(summary(many[id]), summary(one), f'frame {i}')
                    np.testing.assert_array_equal(many[id].mask, one.mask)

    def test_update_as_tracker_update(self):
        single, multi = projtrack.Tracker(), projtrack.MultiTracker()
        single.init(frame(0), box_of(*red(0)))
        multi.add(frame(0), box_of(*red(0)))
        multi.update(frame(0))
        for i in range(1, 8):
            ok, box = single.update(frame(i))
            ok_all, boxes = multi.update(frame(i))
            self.assertEqual(ok_all, ok)
            self.assertEqual(tuple(boxes[0]), box)


class Update(unittest.TestCase):
    """update() -> (ok, boxes) as cv2.legacy.MultiTracker.update: boxes a float64 array, one
    (x, y, w, h) row per object in the order of ids."""

    def test_shapes(self):
        tracker = projtrack.MultiTracker()
        ok, boxes = tracker.update(frame(0))  # no object: every one (none) measured
        self.assertIs(ok, True)
        self.assertEqual((boxes.dtype, boxes.shape), (np.float64, (0, 4)))
        # Beside a tracker given the same frames to track(): the boxes of its results.
        other = projtrack.MultiTracker()
        for t in (tracker, other):
            a = t.add(frame(0), box=box_of(*red(0)))
            b = t.add(frame(0), point=blue(0)[:2])
        for i in range(6):
            ok, boxes = tracker.update(frame(i))
            results = other.track(frame(i))
            self.assertIs(ok, True)
            self.assertIsInstance(boxes, np.ndarray)
            self.assertEqual((boxes.dtype, boxes.shape), (np.float64, (2, 4)))
            self.assertEqual([tuple(row) for row in boxes], [r.box for r in results.values()])
        x, y, w, h = boxes[0]
        self.assertTrue(x <= red(5)[0] <= x + w and y <= red(5)[1] <= y + h, boxes)
        tracker.remove(a)
        other.remove(a)
        ok, boxes = tracker.update(frame(6))
        self.assertEqual(boxes.shape, (1, 4))
        self.assertEqual(tuple(boxes[0]), other.track(frame(6))[b].box)

    def test_not_ok_when_one_object_has_no_features(self):
        tracker = projtrack.MultiTracker()
        tracker.add(frame(0), point=red(0)[:2])
        tracker.update(frame(0))
        # A start on a flat grey frame finds nothing to measure: that object has no features.
        flat = np.full((H, W, 3), 120, np.uint8)
        tracker.add(flat, point=(300, 20))
        ok, boxes = tracker.update(flat)
        self.assertIs(ok, False)
        self.assertEqual(boxes.shape, (2, 4))
        self.assertEqual(tuple(boxes[1]), (0, 0, 0, 0))


class Ids(unittest.TestCase):
    def test_never_reused(self):
        tracker = projtrack.MultiTracker(max_objects=2)
        a = tracker.add(frame(0), point=red(0)[:2])
        b = tracker.add(frame(0), point=blue(0)[:2])
        tracker.remove(a)
        self.assertEqual(tracker.ids, [b])
        c = tracker.add(frame(0), point=red(0)[:2])  # the same place again: a new object
        self.assertEqual(c, 3)
        self.assertEqual(tracker.ids, [b, c])
        self.assertEqual(list(tracker.track(frame(0))), [b, c])
        tracker.clear()
        self.assertEqual((tracker.ids, len(tracker)), ([], 0))
        self.assertEqual(tracker.add(frame(0), point=blue(0)[:2]), 4)
        for gone in (a, c):
            with self.assertRaisesRegex(ValueError, rf'no object of id {gone} \(ids: \[4\]\)'):
                tracker.remove(gone)
            with self.assertRaisesRegex(ValueError, rf'mask: no object of id {gone}'):
                tracker.mask(gone)

    def test_mask_before_any_frame_is_none(self):
        tracker = projtrack.MultiTracker()
        self.assertIsNone(tracker.mask(tracker.add(frame(0), point=red(0)[:2])))


class Errors(unittest.TestCase):
    """Bad input raises, with a message that says what was wrong, and changes nothing."""

    def setUp(self):
        self.tracker = projtrack.MultiTracker(max_objects=2)
        self.a = self.tracker.add(frame(0), box=box_of(*red(0)))

    def tearDown(self):
        self.assertEqual(self.tracker.ids, [self.a])  # every refusal left it as it was

    def test_refused_starts(self):
        f = frame(0)
        refused = {
            'outside': (dict(point=(400, 50)),
                        r'point: \(400, 50\) lies outside the 320x240 frame'),
            'box outside': (dict(box=(330, 10, 20, 20)), r'box: .* lies outside the 320x240'),
            '0-sized box': (dict(box=(10, 10, 0, 20)),
                            'box: its width and height must be at least 1 px'),
            'empty mask': (dict(mask=np.zeros((H, W), bool)), 'mask: no pixel is set'),
            'mask size': (dict(mask=np.ones((10, 10), bool)),
                          r'mask: an \(H, W\) = \(240, 320\) array expected'),
            'on object 1': (dict(point=red(0)[:2]), 'add: object 1 is there already'),
            'box on it': (dict(box=(60, 85, 20, 20)), 'add: object 1 is there already'),
            'mask on it': (dict(mask=ellipse(*red(0))), 'add: object 1 is there already'),
            'several': (dict(point=(10, 10), box=(0, 0, 5, 5)), 'not several'),
            'NaN': (dict(point=(float('nan'), 3)), 'is no pixel coordinate'),
            'count': (dict(point=(1, 2, 3)), r'point: \(x, y\) expected, not 3 numbers'),
        }
        for name, (kw, message) in refused.items():
            with self.subTest(name):
                with self.assertRaisesRegex(ValueError, message):
                    self.tracker.add(f, **kw)
        self.tracker.add(f, point=blue(0)[:2])  # the second of two
        with self.assertRaisesRegex(ValueError, 'add: already following 2 objects'):
            self.tracker.add(f, point=(20, 20))
        self.tracker.remove(2)

    def test_types(self):
        f = frame(0)
        wrong = {
            'no start': ((f,), {}, 'add\\(\\) needs where the object is'),
            'text point': ((f,), dict(point='ab'),
                           'point: a sequence of numbers expected, not str'),
            'text x': ((f,), dict(point=('a', 2)), 'point: a number expected, not str'),
            'number box': ((f,), dict(box=5), 'box: a sequence of numbers expected, not int'),
            'complex mask': ((f,), dict(mask=np.ones((H, W), complex)),
                             'mask: a numeric dtype expected'),
            'list frame': ((f.tolist(),), dict(point=(1, 1)),
                           'frame: a numpy array of uint8 expected, not list'),
            'float frame': ((f.astype(np.float32),), dict(point=(1, 1)),
                            'frame: dtype uint8 expected, not float32'),
            'unknown keyword': ((f,), dict(where_=(1, 1)), 'incompatible function arguments'),
        }
        for name, (args, kw, message) in wrong.items():
            with self.subTest(name):
                with self.assertRaisesRegex(TypeError, message):
                    self.tracker.add(*args, **kw)
        with self.assertRaisesRegex(ValueError, r'frame: gray \(H, W\) or BGR'):
            self.tracker.track(np.zeros(5, np.uint8))
        with self.assertRaisesRegex(TypeError, 'frame: a numpy array'):
            self.tracker.update(None)
        with self.assertRaises(TypeError):
            self.tracker.remove('1')
        with self.assertRaisesRegex(ValueError, r'remove: no object of id 7 \(ids: \[1\]\)'):
            self.tracker.remove(7)
        with self.assertRaisesRegex(ValueError, 't: a finite number'):
            self.tracker.track(f, t=float('inf'))

    def test_settings(self):
        with self.assertRaisesRegex(ValueError, 'max_objects = 0 is not at least 1'):
            projtrack.MultiTracker(max_objects=0)
        with self.assertRaisesRegex(ValueError, 'max_objects = 2147483648'):
            projtrack.MultiTracker(max_objects=2**31)
        with self.assertRaisesRegex(TypeError, "max_objects: a number expected, not str '3'"):
            projtrack.MultiTracker(max_objects='3')
        with self.assertRaisesRegex(TypeError,
                                    "MultiTracker\\(\\) got an unexpected keyword argument 'x'"):
            projtrack.MultiTracker(x=1)
        with self.assertRaisesRegex(TypeError, "Tracker\\(\\) got an unexpected keyword argument "
                                    "'max_objects'"):
            projtrack.Tracker(max_objects=2)
        with self.assertRaisesRegex(ValueError, 'rays'):
            projtrack.MultiTracker(rays=0)
        with self.assertRaisesRegex(TypeError, 'incompatible constructor arguments'):  # Tracker's
            projtrack.MultiTracker(3)
        # Tracker's keywords and max_objects, given back as they were taken.
        t = projtrack.MultiTracker(max_objects=3, method='pixel-filling', fps=25)
        self.assertEqual(t.max_objects, 3)
        self.assertEqual(t.settings, dict(projtrack.Tracker(method='pixel-filling',
                                                            fps=25).settings, max_objects=3))
        self.assertEqual(projtrack.MultiTracker(**t.settings).settings, t.settings)
        self.assertEqual(projtrack.MultiTracker().max_objects, 8)
        self.assertIn('max_objects=8', projtrack.MultiTracker.__doc__)


class Docs(unittest.TestCase):
    """docs/python.md's two-object loop (the block after `<!-- run by test_multi_tracker -->`), as
    written, on opencv-doc's vtest.avi."""

    @unittest.skipUnless(os.path.exists(VTEST), 'opencv-doc is not installed')
    def test_two_object_loop(self):
        with open(os.path.join(ROOT, 'docs', 'python.md')) as f:
            doc = f.read()
        found = re.search(r'<!-- run by test_multi_tracker -->\n```python\n(.*?)```', doc, re.S)
        self.assertIsNotNone(found, 'docs/python.md has no block for this test')
        scope = {}
        exec(compile(found.group(1), 'docs/python.md', 'exec'), scope)  # noqa: S102 -- our docs
        tracker, kept = scope['tracker'], scope['kept']
        self.assertEqual(tracker.frames, 795)
        self.assertEqual(sorted(kept), tracker.ids)
        # Both people are measured on most frames they are in view (the first hundred).
        self.assertTrue(all(n > 100 for n in kept.values()), kept)


if __name__ == '__main__':
    unittest.main(verbosity=2)
