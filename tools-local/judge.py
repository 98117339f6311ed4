"""Scores the harness's results (tools-local/run_clips.sh) against bench/real/truth.

A find is right when its silhouette is the true object: centroid within 1/4 sqrt(area) of the
truth's, area within 1/2-2x. 'rough': the true object, but outside those bounds (centroid within
1/2 sqrt(area), area 1/3-3x). Otherwise false. vtest (the truth is one walker): a find elsewhere
is 'walkers' when >= 60 % of its pixels lie on people (the clip's median background, differences
> 25, grown 5 px) and it covers at most 1/4 of the frame. cube: finds off the cube are listed for
a look by eye (the hand is acceptable)."""
import csv, os, sys
import numpy as np, cv2

OUT = os.environ.get('OUT', '/tmp/mo/cpp')
TRUTH = os.path.join(os.path.dirname(__file__), '..', 'bench', 'real', 'truth')

SOURCES = {  # as tools-local/run_clips.sh reads them
    'cup': os.environ.get('CLIPDIR', '/tmp/mo/clips') + '/cup.mp4',
    'box': os.environ.get('CLIPDIR', '/tmp/mo/clips') + '/box.mp4',
    'vtest': '/usr/share/doc/opencv-doc/examples/data/vtest.avi',
    'megamind': '/usr/share/doc/opencv-doc/examples/data/Megamind.avi',
    'balle1': '/work/main/build/real-clips/root/usr/share/pymecavideo/data/video/balle1-vp9.avi',
    'inertie': '/work/main/build/real-clips/root/usr/share/pymecavideo/data/video/Principe_inertie.avi',
    'force': '/work/main/build/real-clips/root/usr/share/pymecavideo/data/video/Force_constante.avi',
    'magnet': '/work/main/build/real-clips/root/usr/share/pymecavideo/data/video/Effet_force_magnetique.ogv',
    'cube': '/work/main/build/real-clips/root/usr/share/visp-images-data/ViSP-images/mbt/cube/image*.pgm',
    'ellipse': '/work/main/build/real-clips/root/usr/share/visp-images-data/ViSP-images/ellipse-1/image.*.pgm',
}

def frame(n, f):
    """Frame `f` of clip `n`, gray, decoded as the harness decodes it."""
    import glob
    src = SOURCES[n]
    if '*' in src: return cv2.imread(sorted(glob.glob(src))[f], cv2.IMREAD_GRAYSCALE)
    cap = cv2.VideoCapture(src); cap.set(cv2.CAP_PROP_POS_FRAMES, f)
    ok, img = cap.read()
    return cv2.cvtColor(img, cv2.COLOR_BGR2GRAY)

def truth(n):
    return {int(r['frame']): r for r in csv.DictReader(open(os.path.join(TRUTH, n + '.csv')))}

def first_moving(T):
    prev = None
    for f in sorted(T):
        r = T[f]
        if not r['centroid_x']:
            prev = None; continue
        c = (float(r['centroid_x']), float(r['centroid_y']))
        if prev is not None and np.hypot(c[0] - prev[0], c[1] - prev[1]) > 0.5: return f
        prev = c
    return None

def verdict(row, r):
    if not r or not r['centroid_x']: return 'false'
    ta = float(r['area']); d = np.hypot(float(row['cx']) - float(r['centroid_x']), float(row['cy']) - float(r['centroid_y']))
    q = float(row['area']) / ta
    if d <= 0.25 * np.sqrt(ta) and 0.5 <= q <= 2: return 'right'
    if d <= 0.5 * np.sqrt(ta) and 1 / 3 <= q <= 3: return 'rough'
    return 'false'

def people_share(n, f, bg, frame_size):
    cap = people_share.caps.setdefault(n, cv2.VideoCapture('/usr/share/doc/opencv-doc/examples/data/vtest.avi'))
    while people_share.pos < f:
        cap.read(); people_share.pos += 1
    ok, img = cap.read(); people_share.pos += 1
    g = cv2.cvtColor(img, cv2.COLOR_BGR2GRAY)
    fg = (cv2.absdiff(g, bg) > 25).astype(np.uint8)
    fg = cv2.dilate(cv2.morphologyEx(fg, cv2.MORPH_OPEN, np.ones((3, 3), np.uint8)), np.ones((11, 11), np.uint8))
    sil = cv2.imread(os.path.join(OUT, n, '%05d.png' % f), 0)
    fg = cv2.resize(fg, (sil.shape[1], sil.shape[0]), interpolation=cv2.INTER_NEAREST)
    return fg[sil > 0].mean(), (sil > 0).mean()
people_share.caps = {}; people_share.pos = 0

def main(clips):
    for n in clips:
        path = os.path.join(OUT, n, 'results.csv')
        if not os.path.exists(path): continue
        rows = list(csv.DictReader(open(path))); T = truth(n)
        bg = None
        if n == 'vtest':
            cap = cv2.VideoCapture('/usr/share/doc/opencv-doc/examples/data/vtest.avi'); fr = []
            i = 0
            while True:
                ok, img = cap.read()
                if not ok: break
                if i % 5 == 0: fr.append(cv2.cvtColor(img, cv2.COLOR_BGR2GRAY))
                i += 1
            bg = np.median(np.array(fr), axis=0).astype(np.uint8)
            people_share.pos = 0; people_share.caps = {}
        counts = {'right': 0, 'rough': 0, 'false': 0, 'walkers': 0}
        first = None; falses = []; big = 0
        for row in rows:
            if row['found'] != '1': continue
            f = int(row['frame']); v = verdict(row, T.get(f))
            if n == 'vtest' and v == 'false':
                share, cover = people_share(n, f, bg, None)
                if share >= 0.6 and cover <= 0.25: v = 'walkers'
                if cover > 0.25: big += 1
            counts[v] += 1
            if first is None: first = (f, v)
            if v == 'false': falses.append(f)
        found = sum(counts.values())
        print('%-9s frames=%4d moves@%-4s first=%-14s found=%4d right=%4d rough=%3d walkers=%3d false=%3d %s%s' % (
            n, len(rows), first_moving(T), first, found, counts['right'], counts['rough'], counts['walkers'],
            counts['false'], falses[:12], ' over1/4=%d' % big if n == 'vtest' else ''))

if __name__ == '__main__':
    main(sys.argv[1:] or ['cup', 'box', 'inertie', 'force', 'magnet', 'ellipse', 'balle1', 'vtest', 'cube', 'megamind'])
