"""Whether one object moves in a clip, measured on its frames and its truth: the share of the
pixels that change between frames (luma by more than CHANGED levels over two frames) that lie
away from the labelled object (outside its true box grown by half its size on every side: the
object, its motion blur and the hand that moves it). The no-seed target applies to the clips
where that share's median over the in-view frames is at most ONE_MOVER."""
import cv2
import numpy as np

import clip_set

CHANGED = 20      # grey levels (projtrack-real's kChangedLevels)
ONE_MOVER = 1 / 3  # the largest share of the change away from the object for "one object moves"
MIN_CHANGE = 0.001  # a frame with fewer changed pixels than this share shows no motion: skipped


def grey_frames(clip, source):
    if clip.kind == "pgm":
        for path in clip_set.pgm_files(source):
            yield cv2.imread(path, cv2.IMREAD_GRAYSCALE)
        return
    cap = cv2.VideoCapture(source)
    while True:
        ok, frame = cap.read()
        if not ok:
            break
        yield cv2.cvtColor(frame, cv2.COLOR_BGR2GRAY)
    cap.release()


def one_mover(clip, source, rows, start):
    """The median share of the changed pixels that lie away from the object (see above)."""
    history, shares = [], []
    for i, grey in enumerate(grey_frames(clip, source)):
        if i >= len(rows):
            break
        history = (history + [grey.astype(np.int16)])[-3:]
        r = rows[i]
        if i < start + 2 or len(history) < 3 or not r["area"]:
            continue
        changed = np.abs(history[-1] - history[0]) > CHANGED
        total = int(changed.sum())
        if total < MIN_CHANGE * changed.size:
            continue
        x, y, w, h = (int(r[k]) for k in ("x", "y", "width", "height"))
        near = np.zeros_like(changed)
        near[max(0, y - h // 2):y + h + h // 2, max(0, x - w // 2):x + w + w // 2] = True
        shares.append(float((changed & ~near).sum()) / total)
    return float(np.median(shares)) if shares else 0.0
