#!/usr/bin/python3
"""The Python bindings (module projtrack) on generated numpy frames: a disc tracked from a point
and from a box, the silhouette's mask against the reported area, gray and BGR, arrays of any
layout, and bad input raising ValueError or TypeError. Run with PYTHONPATH=<build>/python."""
import math
import threading
import unittest

import numpy as np

import projtrack

W, H, R = 320, 240, 40


def disc(cx, cy, r=R, w=W, h=H):
    """The disc's pixels: a bool (h, w) mask."""
    yy, xx = np.mgrid[0:h, 0:w]
    return (xx - cx) ** 2 + (yy - cy) ** 2 <= r * r


def gray_frame(cx, cy, r=R, w=W, h=H):
    """A bright disc on a dark frame, with a little noise."""
    f = np.full((h, w), 40, np.uint8)
    f[disc(cx, cy, r, w, h)] = 210
    noise = np.random.default_rng(int(cx * 7 + cy)).integers(0, 6, (h, w), dtype=np.uint8)
    return f + noise


def bgr_frame(cx, cy, r=R, w=W, h=H):
    """A dark blue disc on a light wall (BGR), with a little noise."""
    f = np.empty((h, w, 3), np.uint8)
    f[:] = (205, 210, 215)
    f[disc(cx, cy, r, w, h)] = (120, 40, 20)
    noise = np.random.default_rng(int(cx * 7 + cy)).integers(0, 6, (h, w, 3), dtype=np.uint8)
    return f + noise


def path(i):
    """The disc's centre on frame i: right and a little down."""
    return 120 + 5 * i, 110 + 2 * i


def summary(result):
    return (result.status, result.centroid, result.area, result.box, result.inner_point)


class Tracking(unittest.TestCase):
    def follow(self, make_frame, **settings):
        tracker = projtrack.Tracker(**settings)
        self.assertTrue(tracker.init(make_frame(*path(0)), path(0)))
        results = []
        for i in range(1, 16):
            r = tracker.track(make_frame(*path(i)))
            results.append(r)
            cx, cy = path(i)
            self.assertTrue(r.ok, f'frame {i}: {r}')
            self.assertEqual(r.status, 'ok')
            self.assertLess(math.hypot(r.centroid[0] - cx, r.centroid[1] - cy), 2.5, f'frame {i}')
            self.assertAlmostEqual(r.area / (math.pi * R * R), 1, delta=0.1, msg=f'frame {i}')
            x, y, w, h = r.box
            self.assertTrue(x <= cx <= x + w and y <= cy <= y + h, r.box)
        return results

    def test_a_disc_followed_from_a_point_gray_and_bgr(self):
        for make_frame in (gray_frame, bgr_frame):
            for model in ('flow', 'edges'):
                with self.subTest(frame=make_frame.__name__, model=model):
                    self.follow(make_frame, object_model=model)

    def test_every_method(self):
        for method in projtrack.methods():
            with self.subTest(method=method):
                tracker = projtrack.Tracker(method=method)
                self.assertTrue(tracker.init(bgr_frame(160, 120), (160, 120)))
                r = tracker.track(bgr_frame(164, 122))
                self.assertTrue(r.ok, r)
                self.assertLess(math.hypot(r.centroid[0] - 164, r.centroid[1] - 122), 8)

    def test_opencv_pair_from_a_box(self):
        tracker = projtrack.Tracker()
        cx, cy = path(0)
        self.assertIs(tracker.init(bgr_frame(cx, cy), (cx - R, cy - R, 2 * R, 2 * R)), True)
        for i in range(1, 10):
            cx, cy = path(i)
            ok, box = tracker.update(bgr_frame(cx, cy))
            self.assertIs(ok, True)
            self.assertEqual(len(box), 4)
            self.assertTrue(all(isinstance(v, int) for v in box), box)
            for got, want in zip(box, (cx - R, cy - R, 2 * R + 1, 2 * R + 1)):
                self.assertLessEqual(abs(got - want), 4, (box, cx, cy))

    def test_nothing_to_track_before_init(self):
        tracker = projtrack.Tracker()  # manual acquisition: waits for init()
        self.assertEqual(tracker.update(gray_frame(160, 120)), (False, (0, 0, 0, 0)))
        r = tracker.track(gray_frame(160, 120))
        self.assertEqual(r.status, 'no-inner-point')
        self.assertFalse(r.ok)
        self.assertTrue(r.detail)
        self.assertIsNone(r.centroid)
        self.assertIsNone(r.mask)
        self.assertIsNone(r.pose)

    def test_auto_acquisition_finds_the_moving_disc(self):
        tracker = projtrack.Tracker(acquisition='auto')
        found = [tracker.track(bgr_frame(*path(i))).ok for i in range(20)]
        self.assertTrue(any(found), found)

    def test_pose(self):
        tracker = projtrack.Tracker(smoothing=False)
        tracker.init(gray_frame(240, 60), (240, 60))
        r = tracker.track(gray_frame(240, 60))
        x, y, depth = r.pose
        self.assertAlmostEqual(depth, (r.area / (W * H)) ** 0.5, delta=0.05)  # tracker.md
        self.assertAlmostEqual(x, 2 * (r.centroid[0] + 0.5) / W - 1, delta=1e-9)
        self.assertAlmostEqual(y, 2 * (r.centroid[1] + 0.5) / H - 1, delta=1e-9)
        self.assertEqual((r.raw_pose.x, r.raw_pose.y), (x, y))
        self.assertIs(r.push, False)
        self.assertIn('depth=', repr(r.pose))

    def test_a_box_partly_outside_is_clipped(self):
        tracker = projtrack.Tracker()
        self.assertTrue(tracker.init(bgr_frame(30, 30), (-20, -20, 100, 100)))

    def test_settings(self):
        t = projtrack.Tracker(method='pixel-filling', object_model='edges', rays=16, fps=25)
        self.assertEqual(t.settings['method'], 'pixel-filling')
        self.assertEqual(t.settings['object_model'], 'edges')
        self.assertEqual(t.settings['rays'], 16)
        self.assertEqual(t.settings['acquisition'], 'manual')
        self.assertEqual(t.settings['fps'], 25)
        # The keywords are the element's property names; settings gives them back, so a tracker
        # can be made again from them.
        self.assertEqual(projtrack.Tracker(**t.settings).settings, t.settings)
        again = projtrack.Tracker(edge_detector='sobel', edge_threshold_low=20,
                                  edge_threshold_high=90, leak_factor=3, smoothing_beta=0.5,
                                  smoothing_min_cutoff=2, push_threshold=0.2)
        for key, value in [('edge_detector', 'sobel'), ('edge_threshold_low', 20),
                           ('edge_threshold_high', 90), ('leak_factor', 3),
                           ('smoothing_beta', 0.5), ('smoothing_min_cutoff', 2),
                           ('push_threshold', 0.2)]:
            self.assertEqual(again.settings[key], value)
        # The former names still set the same settings.
        former = projtrack.Tracker(model='edges', edge_low=20, edge_high=90)
        self.assertEqual(former.settings['object_model'], 'edges')
        self.assertEqual(former.settings['edge_threshold_low'], 20)
        self.assertEqual(former.settings['edge_threshold_high'], 90)
        self.assertNotIn('model', former.settings)
        self.assertIn("'pixel-filling'", repr(t))
        self.assertEqual(len(projtrack.methods()), 7)
        self.assertIn('gap-tolerant-filling', projtrack.methods())
        self.assertTrue(projtrack.__version__)


class Mask(unittest.TestCase):
    def test_the_mask_is_the_measured_silhouette(self):
        for method, share in (('pixel-filling', 0.01), ('gap-tolerant-filling', 0.1)):
            tracker = projtrack.Tracker(method=method)
            tracker.init(bgr_frame(*path(0)), path(0))
            for i in range(1, 8):
                cx, cy = path(i)
                r = tracker.track(bgr_frame(cx, cy))
                with self.subTest(method=method, frame=i):
                    self.assertTrue(r.ok, r)
                    m = r.mask
                    self.assertEqual((m.shape, m.dtype), ((H, W), np.uint8))
                    self.assertEqual(set(np.unique(m)) - {0, 255}, set())
                    self.assertAlmostEqual(np.count_nonzero(m) / r.area, 1, delta=share)
                    # Where the disc is, and only there.
                    truth = disc(cx, cy)
                    self.assertGreater(np.count_nonzero(m[truth]), 0.95 * truth.sum())
                    self.assertLess(np.count_nonzero(m[~truth]), 0.05 * truth.sum())
                    ys, xs = np.nonzero(m)
                    x, y, w, h = r.box
                    self.assertTrue(x <= xs.min() and xs.max() < x + w + 1, (r.box, xs.min()))

    def test_gray_frames_have_a_mask_too_and_the_edges_model_none(self):
        tracker = projtrack.Tracker()
        tracker.init(gray_frame(160, 120), (160, 120))
        self.assertIsNotNone(tracker.track(gray_frame(162, 120)).mask)
        edges = projtrack.Tracker(object_model='edges')
        edges.init(gray_frame(160, 120), (160, 120))
        r = edges.track(gray_frame(162, 120))
        self.assertTrue(r.ok)
        self.assertIsNone(r.mask)

    def test_no_mask_when_not_asked(self):
        tracker = projtrack.Tracker()
        tracker.init(gray_frame(160, 120), (160, 120))
        self.assertIsNone(tracker.track(gray_frame(162, 120), mask=False).mask)


class MaskStart(unittest.TestCase):
    """A start from a mask (OpenCV's convention: (H, W), non-zero on the object), with the flow
    model that starts from exactly that silhouette, and with the others from its box."""

    def test_the_flow_model_follows_the_given_silhouette(self):
        tracker = projtrack.Tracker(model='flow')
        first = disc(*path(0)).astype(np.uint8) * 255
        self.assertTrue(tracker.init(bgr_frame(*path(0)), first))
        for i in range(1, 12):
            r = tracker.track(bgr_frame(*path(i)))
            self.assertTrue(r.ok, f'frame {i}: {r.status} {r.detail}')
            truth = disc(*path(i))
            iou = np.logical_and(r.mask > 0, truth).sum() / np.logical_or(r.mask > 0, truth).sum()
            self.assertGreater(iou, 0.85, f'frame {i}')
        self.assertEqual(tracker.settings['object_model'], 'flow')

    def test_track_takes_a_mask_array_and_every_model_starts_from_it(self):
        for model in ('flow', 'edges'):
            tracker = projtrack.Tracker(model=model)
            r = tracker.track(bgr_frame(*path(0)), mask=disc(*path(0)))  # a bool mask
            self.assertTrue(r.ok, f'{model}: {r.status} {r.detail}')
            self.assertAlmostEqual(r.area / (math.pi * R * R), 1, delta=0.15, msg=model)
            if model != 'edges':  # the edges model holds no silhouette
                self.assertEqual(r.mask.shape, (H, W))

    def test_bad_masks(self):
        tracker = projtrack.Tracker(model='flow')
        frame = bgr_frame(*path(0))
        with self.assertRaisesRegex(ValueError, 'mask: an \\(H, W\\)'):
            tracker.init(frame, np.zeros((H, W + 1), np.uint8))
        with self.assertRaisesRegex(ValueError, 'no pixel is set'):
            tracker.init(frame, np.zeros((H, W), np.uint8))
        with self.assertRaisesRegex(ValueError, 'not several'):
            tracker.track(frame, point=path(0), mask=disc(*path(0)))

    def test_every_numeric_dtype_is_read_as_it_is_non_zero_on_the_object(self):
        # Each mask is read in its own dtype: a value that a cast to uint8 would make 0 (0.5, 256,
        # -256, inf, 1e-30) is non-zero, so the object; views and other byte orders alike.
        d = disc(*path(0))
        frame = bgr_frame(*path(0))
        masks = {'bool': d, 'float 0.5': d * 0.5, 'float32 1e-30': (d * 1e-30).astype(np.float32),
                 'float16 0.25': (d * 0.25).astype(np.float16), 'float -0.5': d * -0.5,
                 'inf': np.where(d, np.inf, 0), '-inf': np.where(d, -np.inf, 0),
                 'uint16 256': d.astype(np.uint16) * 256, 'int16 -256': d.astype(np.int16) * -256,
                 'uint32 2**24': d.astype(np.uint32) << 24, 'int64 2**40': d.astype(np.int64) << 40,
                 'int8 -1': -d.astype(np.int8), 'uint64 2**63': d.astype(np.uint64) << 63,
                 'big-endian float64': (d * 0.5).astype('>f8'),
                 'big-endian int32': (d.astype(np.int32) << 8).astype('>i4'),
                 'Fortran order': np.asfortranarray(d * 0.5),
                 'every second column': np.repeat(d * 300.0, 2, axis=1)[:, ::2],
                 'bottom-up view': np.flipud(np.flipud(d * 0.5).copy()),
                 'nested list': (d * 256).astype(int).tolist()}
        for name, mask in masks.items():
            with self.subTest(mask=name):
                tracker = projtrack.Tracker(model='flow')
                r = tracker.track(frame, mask=mask)
                self.assertTrue(r.ok, f'{r.status} {r.detail}')
                self.assertAlmostEqual(r.area / d.sum(), 1, delta=0.1)

    def test_mixed_values_keep_every_non_zero_pixel(self):
        # Half the disc 0.5, half 256.0, -0.0 around it: the whole disc, as the bool mask gives.
        d = disc(*path(0))
        mixed = np.where(d, np.where(np.arange(W) < path(0)[0], 0.5, 256.0), -0.0)
        frame = bgr_frame(*path(0))
        a, b = projtrack.Tracker(model='flow'), projtrack.Tracker(model='flow')
        self.assertEqual(summary(a.track(frame, mask=mixed)), summary(b.track(frame, mask=d)))

    def test_nan_is_refused_naming_where(self):
        # NaN is neither zero nor the object: the caller decides, the tracker does not guess.
        tracker = projtrack.Tracker(model='flow')
        frame = bgr_frame(*path(0))
        tracker.init(frame, disc(*path(0)))
        before = summary(tracker.track(bgr_frame(*path(1))))
        for dtype in (np.float16, np.float32, np.float64):
            mask = disc(*path(0)).astype(dtype)
            mask[100, 30] = np.nan
            mask[200, 5] = np.nan
            with self.subTest(dtype=dtype.__name__):
                with self.assertRaisesRegex(ValueError, r'mask: holds NaN at \(x, y\) = '
                                            r'\(30, 100\) \(2 NaNs in all\)'):
                    tracker.track(frame, mask=mask)
                with self.assertRaisesRegex(ValueError, 'mask: holds NaN'):
                    tracker.init(frame, mask)
        # The refused masks left the track as it was.
        self.assertEqual(tracker.track(bgr_frame(*path(2))).status, 'ok', before)

    def test_masks_of_no_number_are_a_type_error(self):
        tracker = projtrack.Tracker(model='flow')
        frame = bgr_frame(*path(0))
        d = disc(*path(0))
        for name, mask in {'complex': d.astype(np.complex128), 'object': d.astype(object),
                           'str': d.astype(str), 'bytes': d.astype(bytes),
                           'datetime': d.astype('datetime64[s]'), 'None': None}.items():
            with self.subTest(mask=name):
                with self.assertRaisesRegex(TypeError, 'mask: a numeric dtype expected'):
                    tracker.track(frame, mask=mask)
                if isinstance(mask, np.ndarray):
                    with self.assertRaisesRegex(TypeError, 'mask: a numeric dtype expected'):
                        tracker.init(frame, mask)

    def test_arrays_of_other_dimensions(self):
        # A 0-d or 3-d array is no point, box or mask: a ValueError saying what is (it was an
        # IndexError or a TypeError about the array's rows); 1-d arrays stay points and boxes.
        tracker = projtrack.Tracker()
        frame = gray_frame(160, 120)
        for where in (np.array(1), np.array(1.5), np.zeros((H, W, 1)), np.zeros((2, 2, 2))):
            with self.subTest(shape=where.shape):
                with self.assertRaisesRegex(ValueError, r'a point \(x, y\), a box \(x, y, w, h\) '
                                            r'or an \(H, W\) mask expected, not an array of '
                                            r'shape \(' + ', '.join(map(str, where.shape))):
                    tracker.init(frame, where)
                with self.assertRaisesRegex(ValueError, r'mask: an \(H, W\) = \(240, 320\) '
                                            r'array expected'):
                    tracker.track(frame, mask=where)
        with self.assertRaisesRegex(ValueError, r'point: \(x, y\) expected, not an array of '
                                    r'shape \(\)'):
            tracker.track(frame, point=np.array(3))
        with self.assertRaisesRegex(ValueError, r'box: \(x, y, width, height\) expected, not an '
                                    r'array of shape \(1, 4\)'):
            tracker.track(frame, box=np.array([[100, 80, 120, 80]]))
        with self.assertRaisesRegex(ValueError, r'mask: an \(H, W\) = \(240, 320\) array '
                                    r'expected, non-zero on the object, not one of shape \(320,\)'):
            tracker.track(frame, mask=np.ones(W))
        self.assertTrue(tracker.init(frame, np.array([160, 120])))
        self.assertTrue(tracker.init(frame, np.array([120, 80, 80, 80], np.uint8)))
        self.assertTrue(tracker.track(frame, box=np.array([120.0, 80, 80, 80])).ok)
        self.assertTrue(tracker.track(frame, point=np.array([160, 120], np.int16)).ok)


class Layouts(unittest.TestCase):
    """Every layout of the same pixels gives the same results as a C-ordered array."""

    def same(self, make_frame, relayout):
        a, b = projtrack.Tracker(), projtrack.Tracker()
        a.init(make_frame(*path(0)), path(0))
        b.init(relayout(make_frame(*path(0))), path(0))
        for i in range(1, 6):
            f = make_frame(*path(i))
            g = relayout(f)
            self.assertTrue(np.array_equal(f, g.reshape(f.shape)))
            ra, rb = a.track(f), b.track(g)
            self.assertTrue(ra.ok)
            self.assertEqual(summary(ra), summary(rb), f'frame {i}')
            self.assertTrue(np.array_equal(ra.mask, rb.mask))

    def test_gray_layouts(self):
        def padded(f):  # rows farther apart than the width: read in place
            big = np.zeros((H + 10, W + 24), np.uint8)
            big[5:H + 5, 8:W + 8] = f
            return big[5:H + 5, 8:W + 8]

        def bottom_up(f):  # a negative row stride
            return np.flipud(np.flipud(f).copy())

        def every_second_column(f):  # pixels two bytes apart
            big = np.zeros((H, 2 * W), np.uint8)
            big[:, ::2] = f
            return big[:, ::2]

        for relayout in (padded, np.asfortranarray, bottom_up, every_second_column,
                         lambda f: f[:, :, None]):
            with self.subTest(layout=getattr(relayout, '__name__', 'HxWx1')):
                self.same(gray_frame, relayout)

    def test_bgr_layouts(self):
        def bgra_view(f):  # BGR read from a BGRA buffer: pixels four bytes apart
            bgra = np.zeros((H, W, 4), np.uint8)
            bgra[..., :3] = f
            return bgra[..., :3]

        def rgb_reversed(f):  # a negative channel stride
            return np.ascontiguousarray(f[..., ::-1])[..., ::-1]

        def padded(f):
            big = np.zeros((H + 2, W + 3, 3), np.uint8)
            big[1:H + 1, 2:W + 2] = f
            return big[1:H + 1, 2:W + 2]

        for relayout in (bgra_view, rgb_reversed, padded, np.asfortranarray):
            with self.subTest(layout=relayout.__name__):
                self.same(bgr_frame, relayout)

    def test_bgra_reads_as_bgr(self):
        def bgra(f):
            out = np.full((H, W, 4), 255, np.uint8)
            out[..., :3] = f
            return out
        a, b = projtrack.Tracker(), projtrack.Tracker()
        a.init(bgr_frame(160, 120), (160, 120))
        b.init(bgra(bgr_frame(160, 120)), (160, 120))
        self.assertEqual(summary(a.track(bgr_frame(163, 121))),
                         summary(b.track(bgra(bgr_frame(163, 121)))))

    def test_read_only_arrays(self):
        f = gray_frame(160, 120)
        f.flags.writeable = False
        tracker = projtrack.Tracker()
        self.assertTrue(tracker.init(f, (160, 120)))


class BadInput(unittest.TestCase):
    def assert_tracker_still_works(self, tracker):
        self.assertTrue(tracker.init(gray_frame(160, 120), (160, 120)))
        self.assertTrue(tracker.update(gray_frame(162, 121))[0])

    def test_bad_settings(self):
        for kwargs, error, words in [
                ({'method': 'nonsense'}, ValueError, 'gap-tolerant-filling'),
                ({'model': 'colour'}, ValueError, 'model'),
                ({'acquisition': 'sometimes'}, ValueError, 'acquisition'),
                ({'rays': 0}, ValueError, 'rays'),
                ({'rays': 1024, 'recursion': 4}, ValueError, 'rays^recursion'),
                ({'grid_size': 0}, ValueError, 'grid_size'),
                ({'max_gap': 99}, ValueError, 'max_gap'),
                ({'edge_threshold_low': 200, 'edge_threshold_high': 100}, ValueError, ''),
                ({'edge_low': float('nan')}, ValueError, ''),
                ({'edge_threshold_low': -1}, ValueError, 'edge_threshold_low'),
                ({'edge_detector': 'prewitt'}, ValueError, 'canny, sobel, input'),
                ({'leak_factor': 0.5}, ValueError, 'leak_factor'),
                ({'smoothing_min_cutoff': 0}, ValueError, 'smoothing_min_cutoff'),
                ({'push_threshold': float('inf')}, ValueError, 'push_threshold'),
                ({'model': 'edges', 'object_model': 'edges'}, TypeError, 'twice'),
                ({'blur': -1}, ValueError, 'blur'),
                ({'max_work': -1}, ValueError, 'max_work'),
                ({'fps': 0}, ValueError, 'fps'),
                ({'rays': '8'}, TypeError, ''),
                # An int beyond C's int (or a double's range) is out of the setting's range.
                ({'rays': 2 ** 40}, ValueError, 'rays = 1099511627776 is outside [3'),
                ({'grid_size': 2 ** 31}, ValueError, 'grid_size = 2147483648 is outside [1'),
                ({'rays': -2 ** 31 - 1}, ValueError, 'rays = -2147483649 is outside [3'),
                ({'blur': 2 ** 64}, ValueError, 'blur = 18446744073709551616 is outside [0'),
                ({'leak_factor': -10 ** 400}, ValueError, 'leak_factor = -1000'),
                ({'fps': -10 ** 400}, ValueError, 'fps = -1000'),
                ({'method': 3}, TypeError, ''),
                ({'colour': 'red'}, TypeError, '')]:
            with self.subTest(**{k: repr(v) for k, v in kwargs.items()}):
                with self.assertRaises(error) as caught:
                    projtrack.Tracker(**kwargs)
                self.assertIn(words, str(caught.exception))
        with self.assertRaises(TypeError):
            projtrack.Tracker('pixel-filling')  # keywords only

    def test_bad_frames(self):
        tracker = projtrack.Tracker()
        for frame, error in [
                ([[1, 2], [3, 4]], TypeError),
                (None, TypeError),
                (b'\0' * 100, TypeError),
                (np.zeros((H, W), np.float32), TypeError),
                (np.zeros((H, W), np.uint16), TypeError),
                (np.zeros((H, W), np.int8), TypeError),
                (np.zeros((H, W), bool), TypeError),
                (np.zeros(W, np.uint8), ValueError),
                (np.zeros((H, W, 2), np.uint8), ValueError),
                (np.zeros((H, W, 5), np.uint8), ValueError),
                (np.zeros((2, H, W, 3), np.uint8), ValueError),
                (np.zeros((0, W), np.uint8), ValueError),
                (np.zeros((H, 0, 3), np.uint8), ValueError),
                (np.zeros((1, 20000), np.uint8), ValueError)]:
            with self.subTest(frame=type(frame).__name__ + str(getattr(frame, 'shape', ''))):
                for call in (tracker.update, tracker.track, lambda f: tracker.init(f, (1, 1))):
                    with self.assertRaises(error):
                        call(frame)
        self.assert_tracker_still_works(tracker)

    def test_bad_points_and_boxes(self):
        tracker = projtrack.Tracker()
        f = gray_frame(160, 120)
        for where, error in [
                ((W, 10), ValueError),  # outside the frame
                ((-1, 10), ValueError),
                ((10, 10, 0, 20), ValueError),  # no width
                ((10, 10, 20, -5), ValueError),
                ((400, 300, 20, 20), ValueError),  # wholly outside
                ((-100, -100, 50, 50), ValueError),
                ((10, 10, 20), ValueError),  # three numbers
                ((10,), ValueError),
                ((), ValueError),
                ((1, 2, 3, 4, 5, 6, 7, 8), ValueError),
                ((float('nan'), 10), ValueError),
                ((float('inf'), 10), ValueError),
                ((2 ** 70, 10), ValueError),
                ((2147483647, 0, 2, 2), ValueError),
                ('ab', TypeError),
                (7, TypeError),
                (None, TypeError),
                ((1, 'a'), TypeError),
                ((1, None), TypeError)]:
            with self.subTest(where=repr(where)):
                with self.assertRaises(error):
                    tracker.init(f, where)
        with self.assertRaises(ValueError):
            tracker.track(f, point=(10, 10), box=(0, 0, 5, 5))
        with self.assertRaises(ValueError):
            tracker.track(f, point=(10, 10, 5, 5))  # a box given as a point
        with self.assertRaises(ValueError):
            tracker.track(f, box=(10, 10))
        with self.assertRaises(TypeError):
            tracker.track(f, t='now')
        with self.assertRaises(ValueError):
            tracker.track(f, t=float('nan'))
        self.assert_tracker_still_works(tracker)

    def test_a_bad_seed_leaves_the_track_as_it_was(self):
        tracker = projtrack.Tracker()
        tracker.init(gray_frame(160, 120), (160, 120))
        with self.assertRaises(ValueError):
            tracker.track(gray_frame(162, 120), point=(-5, -5))
        self.assertTrue(tracker.update(gray_frame(164, 120))[0])

    def test_numpy_numbers_and_floats_are_coordinates(self):
        tracker = projtrack.Tracker()
        self.assertTrue(tracker.init(gray_frame(160, 120), np.array([160.4, 119.6])))
        self.assertEqual(tracker.track(gray_frame(160, 120)).inner_point is None, False)
        self.assertTrue(tracker.init(gray_frame(160, 120), (np.int64(120), np.float32(80), 80, 80)))

    def test_the_frame_size_changes(self):
        tracker = projtrack.Tracker()
        tracker.init(gray_frame(160, 120), (160, 120))
        for f in (gray_frame(80, 60, 20, 160, 120), bgr_frame(320, 240, 80, 640, 480),
                  np.zeros((1, 1), np.uint8), np.zeros((3, 2, 3), np.uint8)):
            r = tracker.track(f)
            self.assertIsInstance(r.status, str)
            if r.mask is not None:
                self.assertEqual(r.mask.shape, f.shape[:2])

    def test_a_new_size_rescales_and_a_new_kind_relearns(self):
        # As the element takes new caps: the track goes on, its centroid and area scaled.
        tracker = projtrack.Tracker()
        tracker.init(bgr_frame(160, 120), (160, 120))
        r = tracker.track(bgr_frame(160, 120))
        self.assertEqual(r.status, 'ok', r.detail)
        area = r.area
        r = tracker.track(bgr_frame(80, 60, R // 2, W // 2, H // 2))
        self.assertEqual(r.status, 'ok', r.detail)
        self.assertAlmostEqual(r.centroid[0], 80, delta=1.5)
        self.assertAlmostEqual(r.area, area / 4, delta=0.1 * area / 4)
        r = tracker.track(gray_frame(80, 60, R // 2, W // 2, H // 2))
        self.assertEqual(r.status, 'ok', r.detail)
        self.assertAlmostEqual(r.area, area / 4, delta=0.1 * area / 4)

    def test_a_bad_seed_with_a_new_size_leaves_the_track_as_it_was(self):
        tracker = projtrack.Tracker()
        tracker.init(gray_frame(160, 120), (160, 120))
        with self.assertRaises(ValueError):
            tracker.track(gray_frame(80, 60, R // 2, W // 2, H // 2), point=(500, 5))
        r = tracker.track(gray_frame(162, 120))
        self.assertEqual(r.status, 'ok', r.detail)
        self.assertAlmostEqual(r.centroid[0], 162, delta=1.5)

    def test_threads_share_a_tracker_safely(self):
        tracker = projtrack.Tracker(acquisition='auto')
        frames = [bgr_frame(*path(i)) for i in range(6)]
        errors = []

        def work():
            try:
                for f in frames:
                    tracker.track(f)
            except Exception as e:  # noqa: BLE001 -- reported below
                errors.append(e)
        threads = [threading.Thread(target=work) for _ in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(errors, [])
        self.assertEqual(tracker.frames, 24)


if __name__ == '__main__':
    unittest.main(verbosity=2)
