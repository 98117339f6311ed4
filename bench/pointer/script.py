"""The 3D-mouse benchmark's scripts: where the object is at every instant, and which gestures it
makes when. The truth of the benchmark is read from here, never from projtrack.

A sequence's depth (the object's scale, 1 at rest) is a slow drift (a hand that drifts toward
and away from the camera while pointing) times its gestures:
- push: a raised cosine of `depth` (+15 % to +50 % of scale) over `duration` (0.15 to 0.6 s);
  its truth is its peak. A double push is two of them a moment apart: two pushes.
- press: a rise of `depth` over `rise`, held for `hold` while the object is dragged sideways,
  a fall over `fall`; its truths are the press when the rise ends and the release when the fall
  ends.
x and y wander all the time (the gestures are made while moving), and the object turns a little.
"""
import dataclasses
import math
import random

import scene

FPS = 30
WIDTH, HEIGHT = 640, 480
SIZES = (0.05, 0.10, 0.20, 0.40)  # the object's larger side over the frame's height, at rest
PUSH_DEPTHS = (0.15, 0.25, 0.35, 0.50)    # the grid every size is tried on...
PUSH_DURATIONS = (0.15, 0.30, 0.45, 0.60)  # ...one (depth, duration) per push
DRIFTS = (0.0, 0.1, 0.2, 0.3)             # amplitude of the slow drift of depth
SEED = 26    # the documented run's
START = 2.5   # s: the first gesture, once the element has found the object
GAP = (1.2, 1.8)  # s between one gesture's end and the next one's start


@dataclasses.dataclass
class Gesture:
    kind: str          # "push" or "press" (a press brings its release)
    start: float       # s
    depth: float       # relative rise of scale
    rise: float        # s (a push: half its duration)
    hold: float = 0.0  # s at the top (a push: 0)
    fall: float = 0.0  # s
    drag: tuple = (0.0, 0.0)  # px moved sideways while held

    @property
    def end(self):
        return self.start + self.rise + self.hold + self.fall

    def scale(self, t):
        """The gesture's factor on scale at `t`: 1 outside it."""
        u = t - self.start
        if u <= 0 or u >= self.rise + self.hold + self.fall:
            return 1.0
        if u < self.rise:
            w = u / self.rise
        elif u < self.rise + self.hold:
            w = 1.0
        else:
            w = 1.0 - (u - self.rise - self.hold) / self.fall
        return 1.0 + self.depth * (1 - math.cos(math.pi * w)) / 2

    def offset(self, t):
        """How far the drag has moved the object at `t` (px): out while held, back over the
        next second and a half."""
        if self.kind != "press":
            return 0.0, 0.0
        a, b = self.start + self.rise, self.start + self.rise + self.hold
        if t <= a:
            w = 0.0
        elif t <= b:
            w = (1 - math.cos(math.pi * (t - a) / (b - a))) / 2
        else:
            w = max(0.0, 1 - (t - b) / 1.5)
        return self.drag[0] * w, self.drag[1] * w

    def truths(self):
        """The events this gesture must give: (kind, time in s)."""
        if self.kind == "push":
            return [("push", self.start + self.rise)]
        return [("press", self.start + self.rise), ("release", self.end)]


@dataclasses.dataclass
class Pose:
    x: float
    y: float
    scale: float
    angle: float


@dataclasses.dataclass
class Sequence:
    name: str
    object: str
    background: str
    size: float
    drift: float         # amplitude of the slow drift of scale
    drift_period: float  # s
    noise: float         # grey levels, standard deviation
    duration: float      # s
    gestures: list
    seed: int
    width: int = WIDTH
    height: int = HEIGHT
    fps: int = FPS
    blur_samples: int = 4
    wander: tuple = ()   # per axis: (amplitude px, period s, phase)

    def frames(self):
        return int(round(self.duration * self.fps))

    def pixels_per_sprite_pixel(self):
        """The object's scale at rest: its larger side is `size` × the frame's height."""
        sp = scene.sprite(self.object)
        return self.size * self.height / max(sp.width, sp.height)

    def drift_factor(self, t):
        return 1 + self.drift * math.sin(2 * math.pi * t / self.drift_period)

    def pose(self, t):
        scale = self.drift_factor(t)
        dx = dy = 0.0
        for g in self.gestures:
            scale *= g.scale(t)
            ox, oy = g.offset(t)
            dx, dy = dx + ox, dy + oy
        (ax, px, fx), (ay, py, fy) = self.wander
        x = self.width / 2 + ax * math.sin(2 * math.pi * t / px + fx) + dx
        y = self.height / 2 + ay * math.sin(2 * math.pi * t / py + fy) + dy
        return Pose(x, y, scale, 4 * math.sin(2 * math.pi * t / 5.3 + fx))

    def light(self, t):
        return 1 + 0.08 * math.sin(2 * math.pi * t / 9 + self.seed)

    def truths(self):
        """Every event the sequence must give, in time order: (kind, time s, gesture index)."""
        out = [(k, t, i) for i, g in enumerate(self.gestures) for k, t in g.truths()]
        return sorted(out, key=lambda e: e[1])


def _max_extent(obj, size, drift, gestures):
    """Half the object's width and height (px) at its largest scale, turned a little."""
    sp = scene.sprite(obj)
    top = max([1.0] + [1 + g.depth for g in gestures]) * (1 + drift)
    s = size * HEIGHT / max(sp.width, sp.height) * top
    turn = 0.08 * max(sp.width, sp.height)  # ±4° turn: a little of the other side shows
    return s * (sp.width + turn) / 2, s * (sp.height + turn) / 2


def _schedule(rng, pushes):
    """The gestures: the given single pushes, one double push and one press, shuffled, spaced."""
    kinds = [("push", p, d) for p, d in pushes] + [("double", None, None), ("press", None, None)]
    rng.shuffle(kinds)
    out, t = [], START
    for kind, p, d in kinds:
        if kind == "push":
            out.append(Gesture("push", t, p, d / 2, 0.0, d / 2))
        elif kind == "double":  # a double click: two short pushes a moment apart
            p = rng.uniform(0.15, 0.5)
            d1, d2, gap = rng.uniform(0.15, 0.35), rng.uniform(0.15, 0.35), rng.uniform(0.15, 0.35)
            out.append(Gesture("push", t, p, d1 / 2, 0.0, d1 / 2))
            out.append(Gesture("push", t + d1 + gap, p, d2 / 2, 0.0, d2 / 2))
        else:  # a drag: forward, held while moving sideways, back
            side = rng.choice((-1, 1)) * rng.uniform(0.15, 0.3) * WIDTH
            out.append(Gesture("press", t, rng.uniform(0.15, 0.5), rng.uniform(0.15, 0.3),
                               rng.uniform(1.0, 2.0), rng.uniform(0.15, 0.3),
                               (side, rng.uniform(-0.1, 0.1) * HEIGHT)))
        t = out[-1].end + rng.uniform(*GAP)
    return out, t


def _fit_wander(rng, obj, size, drift, gestures):
    """x and y wandering (sinusoids of random period and phase) as widely as the frame allows
    with the object whole in view at its largest and the drags added."""
    half_w, half_h = _max_extent(obj, size, drift, gestures)
    drag_x = max([abs(g.drag[0]) for g in gestures] + [0.0])
    drag_y = max([abs(g.drag[1]) for g in gestures] + [0.0])
    room_x = max(WIDTH / 2 - half_w - drag_x - 4, 0.0)
    room_y = max(HEIGHT / 2 - half_h - drag_y - 4, 0.0)
    return ((room_x * rng.uniform(0.6, 1.0), rng.uniform(4, 8), rng.uniform(0, 2 * math.pi)),
            (room_y * rng.uniform(0.6, 1.0), rng.uniform(3, 7), rng.uniform(0, 2 * math.pi)))


def _clamp_drags(gestures, obj, size, drift):
    """Drags shortened so that, with the object at its largest, they fit in the frame."""
    half_w, half_h = _max_extent(obj, size, drift, gestures)
    for g in gestures:
        if g.kind == "press":
            mx, my = max(WIDTH / 2 - half_w - 4, 0), max(HEIGHT / 2 - half_h - 4, 0)
            g.drag = (max(-mx, min(mx, g.drag[0])), max(-my, min(my, g.drag[1])))


def gesture_sequences(seed=SEED):
    """Every size × object once: 16 sequences. Each holds four single pushes from the grid of
    push depth × duration (the four sequences of one size hold all sixteen), two pushes of
    random depth and duration, a double push and a press; drift, background and noise vary."""
    grid = [(p, d) for p in PUSH_DEPTHS for d in PUSH_DURATIONS]
    out = []
    for i, (size, obj) in enumerate((s, o) for s in SIZES for o in scene.OBJECTS):
        rng = random.Random(seed * 1000 + i)
        j = i % 4
        pushes = [grid[(4 * j + k * 5) % 16] for k in range(4)]  # a Latin square over the grid
        pushes += [(rng.uniform(0.15, 0.5), rng.uniform(0.15, 0.6)) for _ in range(2)]
        drift = DRIFTS[(i + i // 4) % 4]
        gestures, end = _schedule(rng, pushes)
        _clamp_drags(gestures, obj, size, drift)
        seq = Sequence(f"{obj}-{round(100 * size)}", obj,
                       scene.BACKGROUNDS[i % len(scene.BACKGROUNDS)], size, drift,
                       rng.uniform(8, 12), rng.choice((2.0, 4.0, 6.0)), end + 1.0, gestures,
                       seed * 1000 + i)
        seq.wander = _fit_wander(rng, obj, size, drift, gestures)
        out.append(seq)
    return out


def idle_sequences(seed=SEED):
    """No gesture at all: a hand pointing around, drifting toward and away from the camera by
    the most the benchmark allows, once per size."""
    out = []
    for i, size in enumerate(SIZES):
        rng = random.Random(seed * 1000 + 500 + i)
        obj = list(scene.OBJECTS)[(i + 1) % len(scene.OBJECTS)]
        seq = Sequence(f"idle-{obj}-{round(100 * size)}", obj,
                       scene.BACKGROUNDS[(i + 3) % len(scene.BACKGROUNDS)], size, 0.3,
                       rng.uniform(8, 12), rng.choice((2.0, 4.0, 6.0)), 15.0, [],
                       seed * 1000 + 500 + i)
        seq.wander = _fit_wander(rng, obj, size, 0.3, [])
        out.append(seq)
    return out


def quick_sequences():
    """The smoke run's: a short sequence with a press and a push, and an idle one."""
    a = [s for s in gesture_sequences() if s.name == "apple-20"][0]
    b = [s for s in idle_sequences() if s.name == "idle-squirrel-20"][0]
    a.gestures = [g for g in a.gestures if g.kind == "press"][:1] + \
                 [g for g in a.gestures if g.kind == "push"][:1]
    a.gestures[0].start, a.gestures[1].start = START, START + 3.5
    a.duration = a.gestures[1].end + 1.0
    b.duration = 5.0
    return [a, b]
