"""Contact sheet of a clip's finds: the frame, the found silhouette (red), the truth's box (green).
Usage: sheet.py <clip> <frames,...> <out.png>"""
import csv, os, sys
import numpy as np, cv2
sys.path.insert(0, os.path.dirname(__file__))
from judge import OUT, truth, frame
n, frames, out = sys.argv[1], [int(x) for x in sys.argv[2].split(',')], sys.argv[3]
T = truth(n); tiles = []
for f in frames:
    img = cv2.cvtColor(frame(n, f), cv2.COLOR_GRAY2BGR)
    p = os.path.join(OUT, n, '%05d.png' % f)
    if os.path.exists(p):
        s = cv2.resize(cv2.imread(p, 0), (img.shape[1], img.shape[0]), interpolation=cv2.INTER_NEAREST)
        c, _ = cv2.findContours((s > 0).astype(np.uint8), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_NONE)
        cv2.drawContours(img, c, -1, (0, 0, 255), 2)
    r = T.get(f)
    if r and r['x']:
        x, y, w, h = [int(r[k]) for k in ('x', 'y', 'width', 'height')]
        cv2.rectangle(img, (x, y), (x + w, y + h), (0, 255, 0), 1)
    cv2.putText(img, str(f), (5, 25), 0, 0.8, (0, 255, 255), 2)
    k = 320 / img.shape[1]; tiles.append(cv2.resize(img, None, fx=k, fy=k))
h = max(t.shape[0] for t in tiles); tiles = [cv2.copyMakeBorder(t, 0, h - t.shape[0], 0, 0, 0) for t in tiles]
while len(tiles) % 4: tiles.append(np.zeros_like(tiles[0]))
cv2.imwrite(out, np.vstack([np.hstack(tiles[i:i + 4]) for i in range(0, len(tiles), 4)]))
