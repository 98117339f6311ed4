#!/usr/bin/python3
"""Ground truth for real clips shipped in Debian packages: one object's silhouette on every
frame, made by colour / shape / motion segmentation rules, never from any tracker's output.

    label_clips.py CLIPS_ROOT OUT_DIR [--sheets DIR] [--only CLIP,...]

CLIPS_ROOT is a directory into which the packages were unpacked with `dpkg -x` (so that it holds
usr/share/pymecavideo/..., usr/share/visp-images-data/..., usr/share/doc/opencv-doc/...); a
file missing there is looked for at the same path under / (an installed package). Writes
OUT_DIR/<clip>.csv (per frame: centroid, area, bounding box, the silhouette's point farthest from
its border, mean luma for checking that a decoder gives the same frames; area 0 and empty fields
where the object is not in view) and OUT_DIR/<clip>_outlines.csv.gz (the silhouette's outer and
hole contours, simplified to within one pixel). With --sheets, contact sheets with the silhouette
outlined, for checking by eye. Hand corrections are read from label_clips_corrections.csv next to this
script. truth/README.md says what each label is, how it was checked and its known errors.

Videos are decoded with cv2.VideoCapture (FFmpeg, full-range BGR); pgm sequences are read with
cv2.imread in sorted name order. Frame numbers count from 0 in decoding order. The rules of each
clip are in label_rules.py (pymecavideo, visp-images-data) and label_rules_ocv.py (opencv-doc).
"""
import argparse
import csv
import glob
import gzip
import os

import cv2
import numpy as np

from label_rules import (balle1_masks, cube_masks, ellipse_masks, force_masks, gray, hull_mask,
                         inertie_masks, magnet_masks)
from label_rules_ocv import megamind_masks, vtest_masks
from truth_geometry import farthest_inside
from truth_geometry import outlines_of as outlines

HERE = os.path.dirname(os.path.abspath(__file__))
MECA = 'usr/share/pymecavideo/data/video/'
VISP = 'usr/share/visp-images-data/ViSP-images/'
OCV = 'usr/share/doc/opencv-doc/examples/data/'


# ----------------------------------------------------------------------------------------------
# hand corrections (label_clips_corrections.csv: clip,first,last,op,shape,coords,why)

def load_corrections(path):
    rows = []
    if os.path.exists(path):
        with open(path, newline='') as fh:
            for r in csv.DictReader(line for line in fh if not line.startswith('#')):
                r['first'], r['last'] = int(r['first']), int(r['last'])
                rows.append(r)
    return rows


def shape_mask(shape, coords, frame, first, last, size):
    """A box `x,y,w,h` (or `x,y,w,h>x,y,w,h`, moved linearly from frame `first` to `last`), a
    point `x,y` (or `x,y>x,y`, moved likewise) or a polygon `x:y x:y ...`, drawn filled."""
    h, w = size
    m = np.zeros((h, w), np.uint8)
    if shape == 'point':
        parts = [np.array([float(v) for v in p.split(',')]) for p in coords.split('>')]
        t = 0.0 if len(parts) == 1 or last == first else (frame - first) / (last - first)
        x, y = parts[0] + t * (parts[-1] - parts[0])
        if 0 <= round(x) < w and 0 <= round(y) < h:
            m[int(round(y)), int(round(x))] = 1
    elif shape == 'box':
        parts = [np.array([float(v) for v in p.split(',')]) for p in coords.split('>')]
        t = 0.0 if len(parts) == 1 or last == first else (frame - first) / (last - first)
        x, y, bw, bh = parts[0] + t * (parts[-1] - parts[0])
        cv2.rectangle(m, (int(round(x)), int(round(y))),
                      (int(round(x + bw)) - 1, int(round(y + bh)) - 1), 1, -1)
    elif shape == 'poly':
        pts = np.array([[int(v) for v in p.split(':')] for p in coords.split()], np.int32)
        cv2.fillPoly(m, [pts], 1)
    else:
        raise SystemExit(f'label_clips: unknown correction shape {shape}')
    return m


def guides_of(clip, corrections):
    """A function (frame, shape) -> the union of the clip's `clip` shapes on that frame, or
    None: labellers that follow an object through merges use them as guides."""
    rows = [r for r in corrections if r['clip'] == clip and r['op'] == 'clip']

    def guide(i, shape):
        mine = [r for r in rows if r['first'] <= i <= r['last']]
        if not mine:
            return None
        m = np.zeros(shape, np.uint8)
        for r in mine:
            m |= shape_mask(r['shape'], r['coords'], i, r['first'], r['last'], shape)
        return m
    return guide


def correct(clip, masks, corrections):
    """Applies the hand corrections of `clip` to the masks (a generator): `absent` empties the
    frame, `clip` keeps only what lies inside the shape, `remove` cuts the shape out, `add`
    paints it in, `hull` replaces the silhouette by the convex hull of it and the shape (a
    convex object's missed corner). In a frame, `clip` comes first, then `remove`, `add`,
    `hull`."""
    mine = [r for r in corrections if r['clip'] == clip]
    order = {'absent': 0, 'clip': 1, 'remove': 2, 'add': 3, 'hull': 4}
    for i, m in enumerate(masks):
        for r in sorted((r for r in mine if r['first'] <= i <= r['last']),
                        key=lambda r: order[r['op']]):
            if r['op'] == 'absent':
                m = np.zeros_like(m)
                continue
            s = shape_mask(r['shape'], r['coords'], i, r['first'], r['last'], m.shape)
            if r['op'] == 'hull':
                m = hull_mask(m | s)
            elif r['op'] == 'clip':
                m = m & s
            elif r['op'] == 'remove':
                m = m & (1 - s)
            elif r['op'] == 'add':
                m = m | s
        yield m


# ----------------------------------------------------------------------------------------------
# reading, writing, contact sheets

def reader(path):
    """A function giving a fresh iterator over the clip's frames (BGR)."""
    if '%' in path:
        names = sorted(glob.glob(os.path.join(os.path.dirname(path), '*.pgm')))
        if not names:
            raise SystemExit(f'label_clips: no frames at {path}')

        def read():
            for n in names:
                yield cv2.cvtColor(cv2.imread(n, cv2.IMREAD_GRAYSCALE), cv2.COLOR_GRAY2BGR)
        return read

    def read():
        cap = cv2.VideoCapture(path)
        if not cap.isOpened():
            raise SystemExit(f'label_clips: cannot read {path}')
        while True:
            ok, frame = cap.read()
            if not ok:
                return
            yield frame
    return read


def draw_outline(img, mask, scale=1.0, offset=(0, 0), colour=(255, 0, 255)):
    cs, _ = cv2.findContours(mask, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_NONE)
    for c in cs:
        pts = ((c.reshape(-1, 2) - offset + 0.5) * scale).astype(np.int32)
        cv2.polylines(img, [pts], True, colour, 1)


def tint(frame, mask):
    """The frame with the silhouette tinted magenta (30 %), so that dark objects show it."""
    out = frame.copy()
    m = mask.astype(bool)
    out[m] = (0.7 * out[m] + 0.3 * np.array([255, 0, 255])).astype(np.uint8)
    return out


def tile(frame, mask, i, sheet):
    """A contact-sheet tile: the whole frame scaled by sheet['scale'], or with sheet['crop']
    = (w, h) a crop of that size around the silhouette's box centre (the last one seen when
    the object is out of view) zoomed by sheet['zoom']; the outline in magenta (and in
    whole-frame tiles a green box around it, small objects being hard to see) over a 30 %
    magenta tint, the frame number, and 'out' when the object is not in view."""
    h, w = frame.shape[:2]
    if 'crop' in sheet:
        cw, ch = sheet['crop']
        cx, cy = sheet['_centre']
        x0 = int(np.clip(cx - cw // 2, 0, max(0, w - cw)))
        y0 = int(np.clip(cy - ch // 2, 0, max(0, h - ch)))
        z = sheet['zoom']
        img = cv2.resize(tint(frame, mask)[y0:y0 + ch, x0:x0 + cw], None, fx=z, fy=z,
                         interpolation=cv2.INTER_NEAREST)
        draw_outline(img, mask[y0:y0 + ch, x0:x0 + cw].copy(), z)
    else:
        z = sheet['scale']
        img = cv2.resize(tint(frame, mask), None, fx=z, fy=z, interpolation=cv2.INTER_AREA)
        draw_outline(img, mask, z)
        if mask.any() and sheet.get('box'):
            x, y, bw, bh = cv2.boundingRect(mask)
            cv2.rectangle(img, (int(x * z) - 4, int(y * z) - 4),
                          (int((x + bw) * z) + 4, int((y + bh) * z) + 4), (0, 255, 0), 1)
    text = str(i) + ('' if mask.any() else ' out')
    cv2.putText(img, text, (3, 15), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (0, 0, 0), 3)
    cv2.putText(img, text, (3, 15), cv2.FONT_HERSHEY_SIMPLEX, 0.5, (0, 255, 255), 1)
    return img


def write_sheets(tiles, cols, per_sheet, path_pattern):
    paths = []
    for s in range(0, len(tiles), per_sheet):
        part = [t for _, t in tiles[s:s + per_sheet]]
        th = max(t.shape[0] for t in part)
        tw = max(t.shape[1] for t in part)
        part = [cv2.copyMakeBorder(t, 0, th - t.shape[0] + 2, 0, tw - t.shape[1] + 2,
                                   cv2.BORDER_CONSTANT, value=(40, 40, 40)) for t in part]
        while len(part) % cols:
            part.append(np.zeros_like(part[0]))
        rows = [np.hstack(part[r:r + cols]) for r in range(0, len(part), cols)]
        path = path_pattern.format(first=tiles[s][0], last=tiles[min(s + per_sheet, len(tiles)) - 1][0])
        cv2.imwrite(path, np.vstack(rows))
        paths.append(path)
    return paths


HEADER = ['frame', 'centroid_x', 'centroid_y', 'area', 'x', 'y', 'width', 'height',
          'inner_x', 'inner_y', 'luma_mean']


def label(clip, spec, clips_root, out_dir, sheets_dir, corrections):
    path = os.path.join(clips_root, spec['path'])
    if not os.path.exists(os.path.dirname(path) if '%' in path else path):
        path = os.path.join('/', spec['path'])
    read = reader(path)
    report = []
    if spec.get('guided'):
        masks = spec['masks'](read, guides=guides_of(clip, corrections), report=report)
    else:
        masks = spec['masks'](read)
    masks = correct(clip, masks, corrections)
    sheet = dict(spec.get('sheet', {'scale': 0.5, 'step': 1}))
    overview = spec.get('overview')
    closeups = set(spec.get('closeups', []))
    tiles, close_tiles, over_tiles, n_in = [], [], [], 0
    first_in = None
    with open(os.path.join(out_dir, clip + '.csv'), 'w', newline='') as fh, \
            gzip.open(os.path.join(out_dir, clip + '_outlines.csv.gz'), 'wt', newline='') as gz:
        w = csv.writer(fh, lineterminator='\n')
        w.writerow(HEADER)
        wo = csv.writer(gz, lineterminator='\n')
        wo.writerow(['frame', 'kind', 'points'])
        for i, (f, m) in enumerate(zip(read(), masks)):
            m = m.astype(np.uint8)
            luma = f'{gray(f).mean():.2f}'
            mo = cv2.moments(m, True)
            if mo['m00'] == 0:
                w.writerow([i, '', '', 0, '', '', '', '', '', '', luma])
            else:
                n_in += 1
                x, y, bw, bh = cv2.boundingRect(m)
                ix, iy = farthest_inside(m)
                if first_in is None:
                    first_in = (i, ix, iy)
                w.writerow([i, f"{mo['m10'] / mo['m00']:.2f}", f"{mo['m01'] / mo['m00']:.2f}",
                            int(mo['m00']), x, y, bw, bh, ix, iy, luma])
                sheet['_centre'] = (x + bw // 2, y + bh // 2)
                for kind, poly in outlines(m):
                    wo.writerow([i, kind, ' '.join(f'{px}:{py}' for px, py in poly)])
            if sheets_dir and '_centre' not in sheet:
                sheet['_centre'] = spec.get('centre0', (f.shape[1] // 2, f.shape[0] // 2))
            if sheets_dir and i % sheet['step'] == 0 and i <= sheet.get('until', i):
                tiles.append((i, tile(f, m, i, sheet)))
            if sheets_dir and overview and i % overview['step'] == 0:
                over_tiles.append((i, tile(f, m, i, overview)))
            if sheets_dir and i in closeups:
                close = dict(spec['closeup'])
                close['_centre'] = sheet['_centre']
                close_tiles.append((i, tile(f, m, i, close)))
    total = i + 1
    if sheets_dir:
        write_sheets(tiles, sheet.get('cols', 6), sheet.get('per_sheet', 48),
                     os.path.join(sheets_dir, clip + '-{first:03d}-{last:03d}.png'))
        if over_tiles:
            write_sheets(over_tiles, overview.get('cols', 8), overview.get('per_sheet', 48),
                         os.path.join(sheets_dir, clip + '-overview-{first:03d}-{last:03d}.png'))
        if close_tiles:
            write_sheets(close_tiles, spec['closeup'].get('cols', 4), 24,
                         os.path.join(sheets_dir, clip + '-closeup-{first:03d}-{last:03d}.png'))
    print(f'{clip}: {total} frames, object in view on {n_in}; first in view {first_in}')
    if report:
        print(f'{clip}: unguided frames where the object may have merged with another: {report}')


# ----------------------------------------------------------------------------------------------

CLIPS = {
    'balle1': dict(path=MECA + 'balle1-vp9.avi', masks=balle1_masks, centre0=(88, 126),
                   sheet=dict(crop=(64, 48), zoom=3, step=3, cols=8, per_sheet=64),
                   overview=dict(scale=0.5, step=15, box=True, cols=5, per_sheet=20),
                   closeup=dict(crop=(32, 32), zoom=8, cols=6),
                   closeups=[0, 2, 4, 6, 8, 10, 88, 90, 92, 94, 96, 98, 100, 102, 104, 106, 108,
                             110, 132, 134, 135, 136, 137, 138, 141, 144, 145, 146, 147, 148, 149, 150,
                             151, 235, 242, 243, 290, 294]),
    'inertie': dict(path=MECA + 'Principe_inertie.avi', masks=inertie_masks,
                    sheet=dict(scale=0.75, step=1, cols=5, per_sheet=30),
                    closeup=dict(crop=(96, 96), zoom=3, cols=5),
                    closeups=list(range(2, 12)) + [25, 26, 27]),
    'force': dict(path=MECA + 'Force_constante.avi', masks=force_masks,
                  sheet=dict(scale=0.75, step=1, cols=5, per_sheet=30),
                  closeup=dict(crop=(96, 96), zoom=3, cols=5),
                  closeups=list(range(2, 12)) + [23, 24, 25]),
    'magnet': dict(path=MECA + 'Effet_force_magnetique.ogv', masks=magnet_masks,
                   sheet=dict(scale=0.75, step=1, cols=5, per_sheet=35),
                   closeup=dict(crop=(96, 96), zoom=3, cols=5),
                   closeups=[2, 3, 4, 14, 15, 16, 17, 18, 32, 33]),
    'cube': dict(path=VISP + 'mbt/cube/image%04d.pgm', masks=cube_masks,
                 sheet=dict(crop=(200, 200), zoom=1, step=3, cols=8, per_sheet=40),
                 closeup=dict(crop=(180, 180), zoom=2, cols=4),
                 closeups=[0, 36, 66, 84, 96, 114, 126, 168, 182, 186, 192, 198, 204, 206,
                           217]),
    'vtest': dict(path=OCV + 'vtest.avi', masks=vtest_masks, guided=True, centre0=(661, 282),
                  sheet=dict(crop=(110, 130), zoom=1.5, step=2, until=158, cols=10, per_sheet=40),
                  overview=dict(scale=0.25, step=20, box=True, cols=8, per_sheet=40),
                  closeup=dict(crop=(100, 120), zoom=3, cols=6),
                  closeups=[23, 25, 28, 31, 34, 37, 40, 44, 49, 53, 54, 55, 56, 57, 58, 61, 63,
                            101, 103, 105, 107, 108, 109, 110, 111, 129, 130, 131, 138, 139,
                            140, 141, 142, 147, 148, 149]),
    'megamind': dict(path=OCV + 'Megamind.avi', masks=megamind_masks,
                     sheet=dict(scale=0.25, step=3, cols=8, per_sheet=48),
                     closeup=dict(crop=(360, 264), zoom=1, cols=4),
                     closeups=[1, 2, 30, 60, 97, 98, 99, 120, 153, 154, 155, 180, 199, 200]),
    'ellipse': dict(path=VISP + 'ellipse-1/image.%04d.pgm', masks=ellipse_masks,
                    sheet=dict(scale=0.5, step=1, cols=6, per_sheet=50)),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('clips_root')
    ap.add_argument('out_dir')
    ap.add_argument('--sheets', help='write contact sheets here for checking by eye')
    ap.add_argument('--only', help='comma-separated clip names (default: all)')
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    if args.sheets:
        os.makedirs(args.sheets, exist_ok=True)
    corrections = load_corrections(os.path.join(HERE, 'label_clips_corrections.csv'))
    for clip in (args.only.split(',') if args.only else CLIPS):
        label(clip, CLIPS[clip], args.clips_root, args.out_dir, args.sheets, corrections)


if __name__ == '__main__':
    main()
